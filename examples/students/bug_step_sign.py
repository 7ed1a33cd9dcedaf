"""Buggy integrator: Heun's method (order 2) whose step computes its own right-hand side with the cross
product reversed, dPi/dt = Omega x Pi instead of (3.8)'s Pi x Omega (the slot euler_3_8 of the file is
right: only the step has the slip). It keeps |Pi|^2 and the energy, both orthogonal to either field,
so only its order claim fails. Expected: the order claim is a FALSE CLAIM and its evidence names the
equation the step follows: "your step follows dPi/dt = Omega x Pi ... (3.8) is Pi x Omega"."""
from correct import *  # noqa: F401,F403
from correct import _cayley, cross, hat, matmul, mscale, omega_3_5

description = "a step integrating dPi/dt = Omega x Pi (examples/students/bug_step_sign.py)"


def _field(I, Pi):
    return cross(omega_3_5(I, Pi), Pi)  # the slip: (3.8) is Pi x Omega


class HeunSignSlip:
    name = "heun_sign_slip"
    claims = {"order": 2, "orthogonality": True}

    @staticmethod
    def rigid_body_step(I, x, h):
        Pi, O = x["Pi"], x["O"]
        k1 = _field(I, Pi)
        k2 = _field(I, [p + h * k for p, k in zip(Pi, k1)])
        nxt = [p + h * (a + b) / 2 for p, a, b in zip(Pi, k1, k2)]
        W = omega_3_5(I, [(a + b) / 2 for a, b in zip(Pi, nxt)])
        return {"Pi": nxt, "O": matmul(O, _cayley(mscale(hat(W), h)))}
