function M = manakov_M(A, W)
  M = A * W + W * A;
end
