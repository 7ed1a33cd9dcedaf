"""Buggy integrator, as a public simulator wrote it: the body's momentum follows (3.8) by the implicit
midpoint rule, but the attitude is turned by the angular velocity I^-1 (O Pi), the body's inverse
inertia applied to the spatial momentum, on the left of O: the inertia is never rotated into space
(I_space = O I O^T, Remark 2.1). Right for a spherical body, wrong otherwise. Expected: its order
claim is a FALSE CLAIM whose evidence says the step turns the body with I^-1 applied to the spatial
momentum, which agrees with (3.5) only when I is spherical."""
from correct import *  # noqa: F401,F403
from correct import Midpoint, _cayley, hat, matmul, matvec, mscale

description = "the attitude turned with the body inertia applied in space (examples/students/bug_step_space_inertia.py)"


class SpaceInertia:
    name = "space_inertia"
    claims = {"order": 2, "orthogonality": True}

    @staticmethod
    def rigid_body_step(I, x, h):
        Pi, O = x["Pi"], x["O"]
        nxt = Midpoint.rigid_body_step(I, x, h)["Pi"]
        mid = [(a + b) / 2 for a, b in zip(Pi, nxt)]
        w_space = [p / i for p, i in zip(matvec(O, mid), I)]  # the flaw: I^-1 in the body frame, pi in space
        return {"Pi": nxt, "O": matmul(_cayley(mscale(hat(w_space), h)), O)}
