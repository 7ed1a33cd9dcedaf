% Semi-implicit Euler as physics engines write it, in the state forms engines keep (the Octave twin
% of semi_implicit_euler.py). An engine steps the angular velocity first (explicitly, with the
% gyroscopic term), then turns the attitude with the new angular velocity and renormalises its
% quaternion. Each integrator keeps its state in another form and says so in its field `state`
% (docs/STUDENTS.md, "State forms"); the suite converts to the notes' (Pi, O) with I, and this file
% converts nothing to them. The conversions an engine does inside its step are its own.
%   ./geomech check examples/engines/semi_implicit_euler.m

function d = geomech_description()
  d = 'semi-implicit Euler in an engine''s state forms (quaternion, omega, Omega, pi)';
end

% Hamilton's product of (w, x, y, z) quaternions (columns).
function c = qmul(a, b)
  c = [a(1) * b(1) - a(2:4)' * b(2:4); a(1) * b(2:4) + b(1) * a(2:4) + cross(a(2:4), b(2:4))];
end

% The rotation matrix (body -> world) of a unit quaternion (w, x, y, z).
function R = rotation(q)
  w = q(1); x = q(2); y = q(3); z = q(4);
  R = [1 - 2 * (y^2 + z^2), 2 * (x * y - w * z), 2 * (x * z + w * y);
       2 * (x * y + w * z), 1 - 2 * (x^2 + z^2), 2 * (y * z - w * x);
       2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x^2 + y^2)];
end

% exp(h hat(v)), by Rodrigues' formula.
function E = axis_angle(v, h)
  a = norm(v);
  if a == 0, E = eye(3); return; end
  k = v / a;
  K = [0, -k(3), k(2); k(3), 0, -k(1); -k(2), k(1), 0];
  E = eye(3) + sin(h * a) * K + (1 - cos(h * a)) * K * K;
end

% Omega <- Omega + h I^-1 ((I Omega) x Omega): Euler's equations (2.2), explicitly.
function W = body_velocity_step(I, W, h)
  W = W + h * cross(I .* W, W) ./ I;
end

% q <- normalise(q + (h/2) q (0, Omega)): the body's rate turns q on the body's side.
function q = turn(q, W, h)
  q = q + h / 2 * qmul(q, [0; W]);
  q = q / norm(q);
end

% The engine's own form: a quaternion (w, x, y, z) and the world-frame angular velocity omega.
function y = world_omega_step(I, x, h)
  R = rotation(x.q);
  W = body_velocity_step(I, R' * x.omega, h);   % world -> body: Omega = R^T omega
  q = turn(x.q, W, h);
  y = struct('q', q, 'omega', rotation(q) * W);  % body -> world with the new attitude
end

% A quaternion stored (x, y, z, w) and the body's Omega.
function y = body_Omega_xyzw_step(I, x, h)
  W = body_velocity_step(I, x.Omega, h);
  q = turn([x.q(4); x.q(1:3)], W, h);
  y = struct('q', [q(2:4); q(1)], 'Omega', W);
end

% A rotation matrix and the spatial angular momentum pi, which a free body keeps.
function y = matrix_pi_step(I, x, h)
  W = (x.O' * x.pi) ./ I;                       % Omega = I^-1 O^T pi
  W = body_velocity_step(I, W, h);
  O = x.O * axis_angle(W, h);
  y = struct('O', O, 'pi', O * (I .* W));       % pi = O I Omega, with the new O
end

function list = geomech_integrators()
  why = 'Octave computes in double';
  list = struct('name', {'semi_implicit_world_omega', 'semi_implicit_body_Omega_xyzw', 'semi_implicit_matrix_pi'}, ...
                'state', {'quaternion_wxyz omega', 'quaternion_xyzw Omega', 'matrix pi'}, ...
                'precision', 'double', 'precision_reason', why, ...
                'claims', {struct('order', 1, 'unit_quaternion', true), struct('order', 1, 'unit_quaternion', true), ...
                           struct('order', 1, 'orthogonality', true)}, ...
                'rigid_body_step', {@world_omega_step, @body_Omega_xyzw_step, @matrix_pi_step});
end
