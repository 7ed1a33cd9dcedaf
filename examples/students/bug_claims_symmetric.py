"""Buggy claim: Heun's method (explicit trapezoid, order 2) for Pi, with the Cayley update of O,
claims to be symmetric (time-reversible). It has order 2, but step(h) then step(-h) does not return
to the start. Expected: the order claim is verified; the symmetric claim is a FALSE CLAIM."""
from correct import *  # noqa: F401,F403
from correct import _cayley, euler_3_8, hat, matmul, mscale, omega_3_5

description = "Heun's method falsely claiming symmetry (examples/students/bug_claims_symmetric.py)"


class Heun:
    name = "heun"
    claims = {"order": 2, "symmetric": True, "orthogonality": True}

    @staticmethod
    def rigid_body_step(I, x, h):
        Pi, O = x["Pi"], x["O"]
        k1 = euler_3_8(I, Pi)
        guess = [p + h * k for p, k in zip(Pi, k1)]
        k2 = euler_3_8(I, guess)
        nxt = [p + h * (a + b) / 2 for p, a, b in zip(Pi, k1, k2)]
        W = omega_3_5(I, [(a + b) / 2 for a, b in zip(Pi, nxt)])
        return {"Pi": nxt, "O": matmul(O, _cayley(mscale(hat(W), h)))}
