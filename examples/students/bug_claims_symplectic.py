"""Buggy claim: Stormer-Verlet for the Clebsch system (3.21) written explicitly, as for a
separable H = T(P) + V(Q). H(Q, P) = h(P x Q) is not separable, and for such an H the first two
stages of Stormer-Verlet are implicit: the explicit version is not symplectic. Beside it, the
implicit midpoint rule on (Q, P), which is. Expected: clebsch_midpoint's symplectic claim is
verified; explicit_verlet's is a FALSE CLAIM."""
from correct import *  # noqa: F401,F403
from correct import clebsch_3_21, mpmath

description = "explicit Stormer-Verlet falsely claiming symplecticity (examples/students/bug_claims_symplectic.py)"


class ClebschMidpoint:
    name = "clebsch_midpoint"
    claims = {"order": 2, "symmetric": True, "symplectic": True}

    @staticmethod
    def clebsch_step(I, z, h):
        Q, P = z
        mQ, mP = list(Q), list(P)
        size = max([1] + [abs(v) for v in Q + P])
        for _ in range(200):  # z_mid = z + (h/2) f(z_mid), to round-off
            dQ, dP = clebsch_3_21(I, mQ, mP)
            nQ = [q + h / 2 * d for q, d in zip(Q, dQ)]
            nP = [p + h / 2 * d for p, d in zip(P, dP)]
            change = max(abs(a - b) for a, b in zip(nQ + nP, mQ + mP))
            mQ, mP = nQ, nP
            eps = 2.0 ** -52 if isinstance(h, float) else mpmath.mpf(2) ** -(mpmath.mp.prec - 1)
            if change <= 4 * eps * size:
                break
        return ([2 * m - q for m, q in zip(mQ, Q)], [2 * m - p for m, p in zip(mP, P)])


class ExplicitVerlet:
    name = "explicit_verlet"
    claims = {"symplectic": True}

    @staticmethod
    def clebsch_step(I, z, h):
        Q, P = z
        P_half = [p + h / 2 * d for p, d in zip(P, clebsch_3_21(I, Q, P)[1])]  # should be implicit in P_half
        Q1 = [q + h * d for q, d in zip(Q, clebsch_3_21(I, Q, P_half)[0])]
        P1 = [p + h / 2 * d for p, d in zip(P_half, clebsch_3_21(I, Q1, P_half)[1])]
        return (Q1, P1)

