"""Buggy: the implicit midpoint's fixed-point iteration stops when two iterates differ by less than
1e-12, an absolute tolerance written for double and for |Pi| of order 1. Its order is still 2 (the
method's own error is larger at the steps an order is measured with), but a step is only solved to
about 1e-14: in 50 digits the Casimir and the energy, which the exact midpoint step keeps, drift by
10^35 units of round-off; and in double too, for a slowly turning body (|Pi| ~ 1e-12 and below,
h scaled to match: the invariant claims' scaled states), where the iteration stops at once.
Expected: the casimir and energy claims are FALSE CLAIMs in double and in mp50; the symmetric
claim fails in both (130 eps in double, more than round-off); the order is verified but for the
scaled states of integrator_converges_in_every_regime (where |Pi| is below 1e-12 the step falls
to first order)."""
from correct import *  # noqa: F401,F403
from correct import _cayley, euler_3_8, hat, matmul, mscale, omega_3_5

description = "midpoint iteration stopped at a hard-coded 1e-12 (examples/students/bug_fixed_point_tolerance.py)"


class MidpointLooseTolerance:
    name = "midpoint_1e12"
    claims = {"order": 2, "symmetric": True, "casimir": True, "energy": True, "orthogonality": True}

    @staticmethod
    def rigid_body_step(I, x, h):
        Pi, O = x["Pi"], x["O"]
        nxt = list(Pi)
        for _ in range(200):
            mid = [(a + b) / 2 for a, b in zip(Pi, nxt)]
            again = [p + h * d for p, d in zip(Pi, euler_3_8(I, mid))]
            change = max(abs(a - b) for a, b in zip(again, nxt))
            nxt = again
            if change < 1e-12:
                break
        W = omega_3_5(I, [(a + b) / 2 for a, b in zip(Pi, nxt)])
        return {"Pi": nxt, "O": matmul(O, _cayley(mscale(hat(W), h)))}
