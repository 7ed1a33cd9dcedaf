function W = omega_3_5(I, P)
  W = P ./ I;
end
