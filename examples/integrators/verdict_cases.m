% Integrators whose true behaviour is known by theory, in Octave: explicit Euler under
% two names (the same step, so the same verdicts, here as in C++ and Python), and an engine that
% refuses fast states, once with its domain declared. See verdict_cases.hpp.
%   ./geomech check examples/integrators/verdict_cases.m

function d = geomech_description()
  d = 'integrators with known behaviour (examples/integrators/verdict_cases.m)';
end

function m = hat(v)
  m = [0, -v(3), v(2); v(3), 0, -v(1); -v(2), v(1), 0];
end

function d = euler_3_8(I, P)
  d = cross(P, P ./ I);
end

function x = explicit_euler_step(I, x0, h)
  x.Pi = x0.Pi + h * euler_3_8(I, x0.Pi);
  x.O = x0.O + h * x0.O * hat(x0.Pi ./ I);
end

function x = guarded_step(I, x0, h)
  if max(abs(x0.Pi ./ I)) >= 2^20
    error('angular velocity out of range');
  end
  x = explicit_euler_step(I, x0, h);
end

function list = geomech_integrators()
  list = struct('name', {'explicit_euler', 'explicit_euler_twin', 'raises_beyond', 'raises_beyond_declared'}, ...
                'claims', {struct('order', 1, 'casimir', true), struct('order', 1, 'casimir', true), ...
                           struct('order', 1), struct('order', 1)}, ...
                'domain', {[], [], [], struct('max_omega', 2^19)}, ...
                'rigid_body_step', {@explicit_euler_step, @explicit_euler_step, @guarded_step, @guarded_step});
end
