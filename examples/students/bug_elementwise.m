% Buggy: `.*` (elementwise) where the matrix product was meant. The reconstruction (2.10)
% dO/dt = O Omega_hat is written O .* hat(Omega). Expected: reconstruction_2_10 FAILS (its own check
% first); hat and vee pass.
%   ./geomech check examples/students/bug_elementwise.m

function d = geomech_description()
  d = 'reconstruction (2.10) with .* (examples/students/bug_elementwise.m)';
end

function m = hat(v)
  m = [0, -v(3), v(2); v(3), 0, -v(1); -v(2), v(1), 0];
end

function v = vee(m)
  v = [m(3, 2); m(1, 3); m(2, 1)];
end

function d = reconstruction_2_10(O, W)
  d = O .* hat(W);   % should be O * hat(W)
end
