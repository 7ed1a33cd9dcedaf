% Dave hands in a folder, one function per file, as MATLAB wants them. manakov_2_34.m is right;
% it calls manakov_Omega.m, which reads its solution back transposed: the first fix is
% manakov_Omega, not manakov_2_34.
function d = manakov_2_34(A, M)
  W = manakov_Omega(A, M);
  d = M * W - W * M;
end
