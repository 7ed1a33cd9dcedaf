% Buggy: Manakov's Omega from A Omega + Omega A = M (2.34) by the Kronecker form of the equation, with
% the solution vector read back row by row: reshape fills columns, so reshape(w, n, n)' is the
% transpose of Omega, that is -Omega. Expected: manakov_Omega FAILS (its own check first), and
% manakov_2_34 with it; manakov_M passes.
%   ./geomech check examples/students/bug_reshape_transposed.m

function d = geomech_description()
  d = 'Manakov Omega read back transposed (examples/students/bug_reshape_transposed.m)';
end

function M = manakov_M(A, W)
  M = A * W + W * A;
end

function W = manakov_Omega(A, M)
  n = size(A, 1);
  w = (kron(eye(n), A) + kron(A', eye(n))) \ M(:);
  W = reshape(w, n, n)';   % should be reshape(w, n, n)
end

function d = manakov_2_34(A, M)
  W = manakov_Omega(A, M);
  d = M * W - W * M;
end
