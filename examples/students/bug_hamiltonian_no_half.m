% Buggy: h = Pi . I^-1 Pi without the 1/2 in (3.4). Expected: hamiltonian_3_4 properties FAIL.
%   ./geomech check examples/students/correct.m
% Vectors arrive as 3x1 columns, matrices as matrices.

function d = geomech_description()
  d = 'bug_hamiltonian_no_half.m';
end

function m = hat(v)
  m = [0, -v(3), v(2); v(3), 0, -v(1); -v(2), v(1), 0];
end

function v = vee(m)
  v = [m(3, 2); m(1, 3); m(2, 1)];
end

function p = pairing(a, b)
  p = trace(a' * b) / 2;
end

function d = euler_2_1(I, W)
  d = [(I(2) - I(3)) * W(2) * W(3) / I(1); (I(3) - I(1)) * W(3) * W(1) / I(2); (I(1) - I(2)) * W(1) * W(2) / I(3)];
end

function d = euler_2_2(I, W)
  d = cross(I .* W, W) ./ I;
end

function d = euler_3_7(I, P)
  d = [(1 / I(3) - 1 / I(2)) * P(2) * P(3); (1 / I(1) - 1 / I(3)) * P(3) * P(1); (1 / I(2) - 1 / I(1)) * P(1) * P(2)];
end

function d = euler_3_8(I, P)
  d = cross(P, P ./ I);
end

function d = euler_matrix_2_12(I, Pi_hat)
  W = hat(vee(Pi_hat) ./ I);
  d = Pi_hat * W - W * Pi_hat;
end

function l = lagrangian_2_5(I, W)
  l = W' * (I .* W) / 2;
end

function P = legendre_3_1(I, W)
  P = I .* W;
end

function W = omega_3_5(I, P)
  W = P ./ I;
end

function h = hamiltonian_3_3(I, P)
  W = P ./ I;
  h = P' * W - lagrangian_2_5(I, W);
end

function h = hamiltonian_3_4(I, P)
  h = P' * (P ./ I);
end

function b = lie_poisson_3_6(P, df, dh)
  b = -P' * cross(df, dh);
end

function b = nambu_3_13(dc, df, dh)
  b = -dc' * cross(df, dh);
end

function x = nambu_motion_3_14(dc, dh)
  x = cross(dc, dh);
end

function b = canonical_bracket(dfdq, dfdp, dhdq, dhdp)
  b = dfdq' * dhdp - dfdp' * dhdq;
end

function J = momentum_map(q, p)
  J = cross(p, q);
end

function r = clebsch_3_21(I, Q, P)
  W = cross(P, Q) ./ I;
  r = {cross(Q, W), cross(P, W)};
end

function d = reconstruction_2_10(O, W)
  d = O * hat(W);
end

function s = spatial_momentum(O, P)
  s = O * P;
end

function S = inertia_space(O, I)
  S = O * diag(I) * O';
end

function M = manakov_M(A, W)
  M = A * W + W * A;
end

function W = manakov_Omega(A, M)
  % solve A W + W A = M (Sylvester equation)
  n = size(A, 1);
  W = reshape((kron(eye(n), A) + kron(A', eye(n))) \ M(:), n, n);
end

function d = manakov_2_34(A, M)
  W = manakov_Omega(A, M);
  d = M * W - W * M;
end

function l = manakov_lagrangian(A, W)
  l = -trace(W * A * W) / 2;
end

function x = midpoint_step(I, x0, h)
  P = x0.Pi;
  nxt = P;
  for it = 1:200
    again = P + h * euler_3_8(I, (P + nxt) / 2);
    change = max(abs(again - nxt));
    nxt = again;
    if change <= 4 * eps * (1 + max(abs(P)))
      break;
    end
  end
  A = h * hat(((P + nxt) / 2) ./ I);
  x.Pi = nxt;
  x.O = x0.O * ((eye(3) - A / 2) \ (eye(3) + A / 2));
end

function list = geomech_integrators()
  list = struct('name', 'midpoint', ...
                'claims', struct('order', 2, 'symmetric', true, 'casimir', true, 'energy', true, 'orthogonality', true), ...
                'rigid_body_step', @midpoint_step);
end
