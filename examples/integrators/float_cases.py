"""Integrators computed in single precision, in Python (numpy.float32), as an engine's float build
behind a Python wrapper computes: the same steps as float_cases.hpp, for the verdicts that must be
the same in every language (tests/float_verdicts.py).

    ./geomech check examples/integrators/float_cases.py --integrator float_midpoint

Each step rounds its input to float32, computes in float32 and returns float32 values; each states
precision = "float", so it is run in double only and judged at float's round-off (eps = 2^-23).
"""
import numpy as np

description = "integrators computed in float32 (examples/integrators/float_cases.py)"

F = np.float32
REASON = "computes every value in numpy.float32, as an engine's float build does"


def _f(v):
    return np.array([F(x) for x in v], dtype=np.float32)


def _hat(w):
    return np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]], dtype=np.float32)


def _cayley(A):
    Id = np.eye(3, dtype=np.float32)
    return np.linalg.solve(Id - A / F(2), Id + A / F(2)).astype(np.float32)


def _midpoint(I, P, O, h):
    nxt = P.copy()
    size = np.max(np.abs(P))
    for _ in range(200):
        mid = (P + nxt) / F(2)
        again = (P + h * np.cross(mid, mid / I)).astype(np.float32)
        change = np.max(np.abs(again - nxt))
        nxt = again
        if change <= F(8) * np.finfo(np.float32).eps * size:
            break
    W = ((P + nxt) / F(2)) / I
    return nxt, (O @ _cayley(h * _hat(W))).astype(np.float32)


def _out(P, O):
    return {"Pi": [float(p) for p in P], "O": [[float(o) for o in row] for row in O]}


class FloatMidpoint:
    """float_cases.hpp's FloatMidpoint: the midpoint rule's claims, each true at float's round-off."""
    name = "float_midpoint"
    precision = "float"
    precision_reason = REASON
    claims = {"order": 2, "symmetric": True, "casimir": True, "energy": True, "orthogonality": True,
              "noether": True, "equivariant": True, "bounded_energy": True}

    @staticmethod
    def rigid_body_step(I, x, h):
        P, O = _midpoint(_f(I), _f(x["Pi"]), np.array(x["O"], dtype=np.float32), F(h))
        return _out(P, O)


class FloatNoGyroscopic:
    """float_cases.hpp's FloatNoGyroscopic: Pi held constant, O turned by Omega = I^-1 Pi."""
    name = "float_no_gyroscopic"
    precision = "float"
    precision_reason = REASON
    claims = {"order": 1}

    @staticmethod
    def rigid_body_step(I, x, h):
        Iv, P = _f(I), _f(x["Pi"])
        O = np.array(x["O"], dtype=np.float32)
        return _out(P, (O @ _cayley(F(h) * _hat(P / Iv))).astype(np.float32))

