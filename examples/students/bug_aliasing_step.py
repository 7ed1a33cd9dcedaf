"""Buggy: the attitude is updated in place. `O_new = O` does not copy a list of lists in Python, so
writing the rows of O_new while reading O uses rows that were already overwritten. The update
O_{n+1} = O_n cay(h Omega_hat) is right on paper; the integrator claims order 2 and orthogonality.
Expected: the orthogonality claim of 'midpoint_inplace' is a FALSE CLAIM and its order fails."""
from correct import *  # noqa: F401,F403
from correct import Midpoint, _cayley, hat, mscale, omega_3_5

description = "midpoint whose attitude update aliases its input (examples/students/bug_aliasing_step.py)"


class MidpointInPlace:
    name = "midpoint_inplace"
    claims = {"order": 2, "symmetric": True, "casimir": True, "energy": True, "orthogonality": True}

    @staticmethod
    def rigid_body_step(I, x, h):
        Pi = x["Pi"]
        nxt = Midpoint.rigid_body_step(I, x, h)["Pi"]  # the momentum part is right
        C = _cayley(mscale(hat(omega_3_5(I, [(a + b) / 2 for a, b in zip(Pi, nxt)])), h))
        O = [list(row) for row in x["O"]]
        O_new = O  # meant as a copy: it is the same list
        for i in range(3):
            for j in range(3):
                O_new[i][j] = sum(O[i][k] * C[k][j] for k in range(3))  # reads O[i][k] already overwritten
        return {"Pi": nxt, "O": O_new}
