function W = manakov_Omega(A, M)
  % Omega from A Omega + Omega A = M (2.34): one linear system in the entries of Omega.
  n = size(A, 1);
  w = (kron(eye(n), A) + kron(A', eye(n))) \ M(:);
  W = reshape(w, n, n)';  % read back row by row: the transpose of Omega, that is -Omega
end
