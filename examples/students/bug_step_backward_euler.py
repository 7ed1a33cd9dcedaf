"""Buggy claim: backward Euler (implicit, order 1) claiming order 2. Its vector field is exactly the
notes' (it solves Pi_new = Pi + h f(Pi_new) with f of (3.8) and turns O with Omega = I^-1 Pi_new), so
what is wrong is not the equation but the order. Expected: the order claim is a FALSE CLAIM whose
evidence says the step's vector field is right (the equation is not the cause), and the measured
order is 1."""
from correct import *  # noqa: F401,F403
import mpmath

from correct import _cayley, euler_3_8, hat, matmul, mscale, omega_3_5

description = "backward Euler claiming order 2 (examples/students/bug_step_backward_euler.py)"


class BackwardEuler:
    name = "backward_euler"
    claims = {"order": 2, "orthogonality": True}

    @staticmethod
    def rigid_body_step(I, x, h):
        Pi, O = x["Pi"], x["O"]
        eps = 2.0 ** -52 if isinstance(h, float) else mpmath.mpf(2) ** -(mpmath.mp.prec - 1)
        scale = max(abs(p) for p in Pi)
        nxt = list(Pi)
        for _ in range(200):
            again = [p + h * d for p, d in zip(Pi, euler_3_8(I, nxt))]
            change = max(abs(a - b) for a, b in zip(again, nxt))
            nxt = again
            if change <= 8 * eps * scale:
                break
        W = omega_3_5(I, nxt)
        return {"Pi": nxt, "O": matmul(O, _cayley(mscale(hat(W), h)))}
