% Buggy claim: the implicit midpoint rule applied to Euler's equations (3.8) keeps |Pi|^2 and the
% energy (both quadratic), and is claimed here to be a Poisson map of the Lie-Poisson bracket too.
% It is not: the midpoint rule is symplectic for canonical systems, not Poisson for (3.6).
% Expected: order, casimir and energy claims verified; the poisson claim is a FALSE CLAIM.
%   ./geomech check examples/students/bug_claims_poisson.m

function d = geomech_description()
  d = 'implicit midpoint falsely claiming to be Poisson (examples/students/bug_claims_poisson.m)';
end

function m = hat(v)
  m = [0, -v(3), v(2); v(3), 0, -v(1); -v(2), v(1), 0];
end

function d = euler_3_8(I, P)
  d = cross(P, P ./ I);
end

function x = midpoint_step(I, x0, h)
  P = x0.Pi;
  nxt = P;
  for it = 1:200
    again = P + h * euler_3_8(I, (P + nxt) / 2);
    change = max(abs(again - nxt));
    nxt = again;
    if change <= 8 * eps * max(abs(P))
      break;
    end
  end
  A = h * hat(((P + nxt) / 2) ./ I);
  x.Pi = nxt;
  x.O = x0.O * ((eye(3) - A / 2) \ (eye(3) + A / 2));
end

function list = geomech_integrators()
  list = struct('name', 'midpoint_poisson', ...
                'claims', struct('order', 2, 'casimir', true, 'energy', true, 'poisson', true), ...
                'rigid_body_step', @midpoint_step);
end
