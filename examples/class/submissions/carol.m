% Week 3, the free rigid body, in Octave (MATLAB's language): every assigned function, right. Octave
% computes in double, so the checks in 50 digits and in rationals do not run for Carol: the summary
% counts them as "d/o" (double only), apart from what she did not write.

function d = geomech_description()
  d = 'Carol: week 3 in Octave';
end

function m = hat(v)
  m = [0, -v(3), v(2); v(3), 0, -v(1); -v(2), v(1), 0];
end

function v = vee(m)
  v = [m(3, 2); m(1, 3); m(2, 1)];
end

function W = omega_3_5(I, P)
  W = P ./ I;
end

function d = euler_3_8(I, P)
  d = cross(P, omega_3_5(I, P));
end

function h = hamiltonian_3_4(I, P)
  h = dot(P, P ./ I) / 2;
end

function c = casimir(P)
  c = dot(P, P) / 2;
end

function d = reconstruction_2_10(O, W)
  d = O * hat(W);
end

function s = spatial_momentum(O, P)
  s = O * P;
end

function M = manakov_M(A, W)
  M = A * W + W * A;
end

function W = manakov_Omega(A, M)
  % A W + W A = M as one linear system in the entries of W (column by column)
  n = size(A, 1);
  W = reshape((kron(eye(n), A) + kron(A', eye(n))) \ M(:), n, n);
end

function d = manakov_2_34(A, M)
  W = manakov_Omega(A, M);
  d = M * W - W * M;
end
