% A correct Octave/MATLAB implementation of every slot (examples/students/correct.m), checked in
% double:   ./geomech check examples/students/correct.m
% Vectors arrive as columns, matrices as matrices, the Lie algebra as 'so3', 'so4' or 'sl2'; a pair
% is returned as a cell {a, b}.

function d = geomech_description()
  d = 'a correct Octave implementation (examples/students/correct.m)';
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

function m = hat_n(v, n)
  % so(n) from n(n-1)/2 coordinates: so(n-1) in the top-left block, the last column from the rest
  if numel(v) ~= n * (n - 1) / 2
    error('hat_n: %d coordinates do not make an element of so(%d)', numel(v), n);
  end
  if n == 2
    m = [0, -v(1); v(1), 0];
  elseif n == 3
    m = hat(v);
  else
    d = (n - 1) * (n - 2) / 2;
    m = zeros(n, n);
    m(1:n - 1, 1:n - 1) = hat_n(v(1:d), n - 1);
    m(1:n - 1, n) = v(d + 1:end);
    m(n, 1:n - 1) = -v(d + 1:end)';
  end
end

function v = vee_n(m)
  n = size(m, 1);
  if n == 2
    v = m(2, 1);
  elseif n == 3
    v = vee(m);
  else
    v = [vee_n(m(1:n - 1, 1:n - 1)); m(1:n - 1, n)];
  end
end

function m = lie_hat(g, x)
  switch g
    case 'so3', m = hat_n(x, 3);
    case 'so4', m = hat_n(x, 4);
    case 'sl2', m = [x(1), x(2); x(3), -x(1)];
    otherwise, error('lie_hat: unknown algebra %s', g);
  end
end

function x = lie_vee(g, m)
  if strcmp(g, 'sl2')
    x = [m(1, 1); m(1, 2); m(2, 1)];
  else
    x = vee_n(m);
  end
end

function a = ad_star(g, xi, mu)
  % (ad*_xi mu)_k = <mu, [xi, e_k]> in coordinates
  d = numel(xi);
  a = zeros(d, 1);
  X = lie_hat(g, xi);
  for k = 1:d
    e = zeros(d, 1);
    e(k) = 1;
    E = lie_hat(g, e);
    a(k) = mu' * lie_vee(g, X * E - E * X);
  end
end

function c = so4_bracket_R6(a, b)
  c = [cross(a(1:3), b(1:3)) + cross(a(4:6), b(4:6)); cross(a(1:3), b(4:6)) - cross(b(1:3), a(4:6))];
end

function c = ad_star_so4_R6(xi, mu)
  c = [cross(mu(1:3), xi(1:3)) + cross(mu(4:6), xi(4:6)); cross(mu(1:3), xi(4:6)) + cross(mu(4:6), xi(1:3))];
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

function l = lagrangian_2_13(I, W_hat)
  l = pairing(hat(I .* vee(W_hat)), W_hat) / 2;
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
  h = P' * (P ./ I) / 2;
end

function h = hamiltonian_2_21(I, Pi_hat)
  W_hat = hat(vee(Pi_hat) ./ I);
  h = pairing(Pi_hat, W_hat) - lagrangian_2_13(I, W_hat);
end

function c = casimir(P)
  c = P' * P / 2;
end

function b = lie_poisson_2_23(Pi_hat, df, dh)
  b = -pairing(Pi_hat, df * dh - dh * df);
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

function d = nambu_3_16(a, x)
  d = [-a(1) * a(3) * x(2) * x(3); -a(2) * a(3) * x(3) * x(1); a(1) * a(2) * x(1) * x(2)];
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

function T = inertia_tensor_2_3(m, X)
  % point masses m(k) at the columns of X (3 x N)
  if size(X, 1) ~= 3 || size(X, 2) ~= numel(m)
    error('inertia_tensor_2_3: X must be 3 x N with N = %d masses', numel(m));
  end
  T = zeros(3, 3);
  for k = 1:numel(m)
    x = X(:, k);
    T = T + m(k) * ((x' * x) * eye(3) - x * x');
  end
end

function s = inertia_bilinear_2_3(m, X, a, b)
  s = 0;
  for k = 1:numel(m)
    s = s + m(k) * cross(a, X(:, k))' * cross(b, X(:, k));
  end
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

function r = manakov_clebsch_3_23(A, Q, P)
  W = manakov_Omega(A, Q' * P - P' * Q);
  r = {Q * W, P * W};
end

function x = midpoint_step(I, x0, h)
  % Newton's method on F(N) = N - P - h f((P + N)/2), f(x) = x x (x ./ I) (3.8): a few iterations
  % where the fixed-point iteration needs tens at h = 1/4. With m = (P + N)/2,
  % dF/dN = Id - h/2 (hat(m) diag(1./I) - hat(m ./ I)).
  P = x0.Pi;
  nxt = P + h * euler_3_8(I, P);
  for it = 1:50
    m = (P + nxt) / 2;
    F = nxt - P - h * euler_3_8(I, m);
    J = eye(3) - (h / 2) * (hat(m) * diag(1 ./ I) - hat(m ./ I));
    delta = J \ F;
    nxt = nxt - delta;
    if max(abs(delta)) <= 8 * eps * max(abs(P))  % relative: the same step in any units
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
