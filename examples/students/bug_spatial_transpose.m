% Buggy: the spatial angular momentum as printed in (2.30) of the notes, pi = O^-1 Pi O, which in
% vectors is O^T Pi; the conserved quantity is O Pi (erratum s2.noether). Expected:
% spatial_momentum FAILS (its own check first), and the report says the result matches the notes'
% misprint; hat, vee and reconstruction_2_10 pass.
%   ./geomech check examples/students/bug_spatial_transpose.m

function d = geomech_description()
  d = 'spatial momentum as printed in (2.30) (examples/students/bug_spatial_transpose.m)';
end

function m = hat(v)
  m = [0, -v(3), v(2); v(3), 0, -v(1); -v(2), v(1), 0];
end

function v = vee(m)
  v = [m(3, 2); m(1, 3); m(2, 1)];
end

function d = reconstruction_2_10(O, W)
  d = O * hat(W);
end

function s = spatial_momentum(O, P)
  s = O' * P;   % (2.30) as printed; the notes mean O * P
end
