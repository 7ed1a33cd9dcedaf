% Octave functions that go wrong in each way a reply can (tests/harness/remote/protocol_tests.cpp,
% OctaveServersAnswerAlike): both Octave servers must answer these calls with the same text.

function m = hat(v)
  % a complex result
  m = [0, -v(3), v(2); v(3), 0, -v(1); -v(2), v(1), 0] + 1i;
end

function v = vee(m)
  % an error two frames down, with its lines
  v = vee_helper(m);
end

function v = vee_helper(m)
  error('vee_helper: refused a %dx%d matrix', size(m, 1), size(m, 2));
end

function p = pairing(a, b)
  % a matrix where a scalar is expected
  p = a * b;
end

function d = euler_3_8(I, P)
  % no value returned
  x = I + P;
end

function l = lagrangian_2_5(I, Omega)
  % a string where a number is expected
  l = 'x';
end

function m = lie_hat(g, x)
  % a cell where a matrix is expected
  m = {g, x};
end

function v = lie_vee(g, m)
  % a three-dimensional array where a vector is expected: written as its entries, as for any array
  v = zeros(2, 2, 2);
end

function m = hat_n(v, n)
  % a three-dimensional array where a matrix is expected
  m = zeros(n, n, 2);
end

function v = vee_n(m)
  % a correct one, with the matrix read back entry by entry
  v = [m(3, 2); m(1, 3); m(2, 1)];
end
