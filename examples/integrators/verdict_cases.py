"""Integrators whose true behaviour is known by theory, in Python: the same steps as
verdict_cases.hpp, for the checks that must say the same in every language, and for
tests/integrator_verdict_tests.py, which calls these steps itself to confirm each verdict by a
computation of its own.

    ./geomech check examples/integrators/verdict_cases.py --integrator explicit_euler

Generic over the scalar: float, mpmath.mpf (50 digits) and Fraction where no root is needed.
"""
import math

description = "integrators with known behaviour (examples/integrators/verdict_cases.py)"


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def euler_3_8(I, P):
    W = [p / i for p, i in zip(P, I)]
    return cross(P, W)


def hat(v):
    z = 0 * v[0]
    return [[z, -v[2], v[1]], [v[2], z, -v[0]], [-v[1], v[0], z]]


def matmul(A, B):
    return [[sum((A[i][k] * B[k][j] for k in range(3)), 0 * A[0][0]) for j in range(3)] for i in range(3)]


def madd(A, B, s=1):
    return [[a + s * b for a, b in zip(ra, rb)] for ra, rb in zip(A, B)]


def eye(like):
    return [[like * 0 + (1 if i == j else 0) for j in range(3)] for i in range(3)]


def energy(I, P):
    return sum(p * p / i for p, i in zip(P, I)) / 2


def explicit_euler_step(I, x, h):
    Pi, O = x["Pi"], x["O"]
    d = euler_3_8(I, Pi)
    W = [p / i for p, i in zip(Pi, I)]
    return {"Pi": [p + h * q for p, q in zip(Pi, d)], "O": madd(O, matmul(O, hat(W)), h)}


def backward_euler_step(I, x, h, tol=None):
    """x' = x + h f(x') for Pi by a fixed-point iteration to round-off, O by the first-order
    update with the new angular velocity."""
    Pi, O = x["Pi"], x["O"]
    size = max(abs(p) for p in Pi)
    eps = tol if tol is not None else (2.0 ** -52 if isinstance(h, float) else h * 0 + 1e-45)
    nxt = list(Pi)
    for _ in range(400):
        again = [p + h * q for p, q in zip(Pi, euler_3_8(I, nxt))]
        change = max(abs(a - b) for a, b in zip(again, nxt))
        nxt = again
        if change <= 8 * eps * size:
            break
    W = [p / i for p, i in zip(nxt, I)]
    return {"Pi": nxt, "O": madd(O, matmul(O, hat(W)), h)}


class ExplicitEuler:
    name = "explicit_euler"
    claims = {"order": 1, "casimir": True}
    rigid_body_step = staticmethod(explicit_euler_step)


class ExplicitEulerTwin:
    """The same step under another name: the same verdicts."""
    name = "explicit_euler_twin"
    claims = {"order": 1, "casimir": True}
    rigid_body_step = staticmethod(explicit_euler_step)


class BackwardEuler:
    name = "backward_euler"
    claims = {"order": 1, "bounded_energy": True}
    rigid_body_step = staticmethod(backward_euler_step)


class AlwaysRaises:
    name = "always_raises"
    claims = {"order": 2}

    @staticmethod
    def rigid_body_step(I, x, h):
        raise RuntimeError("the engine is not initialised")


def _guarded(I, x, h):
    W = max(abs(p / i) for p, i in zip(x["Pi"], I))
    if W >= 2 ** 20:
        raise ValueError("angular velocity out of range")
    return backward_euler_step(I, x, h)


class RaisesBeyond:
    """Raises for |Omega| >= 2^20 and declares nothing."""
    name = "raises_beyond"
    claims = {"order": 1}
    rigid_body_step = staticmethod(_guarded)


class RaisesBeyondDeclared:
    """The same, declaring its domain: nothing faster than 2^19 is drawn."""
    name = "raises_beyond_declared"
    claims = {"order": 1}
    domain = {"max_omega": 2 ** 19}
    rigid_body_step = staticmethod(_guarded)


def _c_cos(t):
    """cos as C and numpy compute it: NaN for an infinite angle (Python's math.cos raises)."""
    return math.cos(t) if math.isfinite(t) else math.nan


def _c_sin(t):
    return math.sin(t) if math.isfinite(t) else math.nan


class FlippedDamping:
    """An engine's step in its own form whose angular damping has its sign flipped (verdict_cases.hpp,
    18): Omega grows without bound and, once |Omega|^2 overflows, the quaternion turns NaN. The run
    must say the energy grew until H is not finite, never that the step raised."""
    name = "flipped_damping"
    state = "quaternion_wxyz Omega"
    precision = "double"
    precision_reason = "written as an engine is, in double"
    claims = {"bounded_energy": True}

    @staticmethod
    def rigid_body_step(I, x, h):
        q, W = x["q"], x["Omega"]
        g = cross([i * w for i, w in zip(I, W)], W)
        W = [w + h * gk / i for w, gk, i in zip(W, g, I)]          # (2.2)
        s = 1 + h * 0.01 * math.sqrt(sum(w * w for w in W))         # the flipped damping
        W = [w * s for w in W]
        n = math.sqrt(sum(w * w for w in W))
        angle = h * n
        axis = [w / n for w in W] if n > 0 else [0.0, 0.0, 0.0]
        t = [_c_cos(angle / 2)] + [_c_sin(angle / 2) * a for a in axis]
        turned = [q[0] * t[0] - q[1] * t[1] - q[2] * t[2] - q[3] * t[3],
                  q[0] * t[1] + q[1] * t[0] + q[2] * t[3] - q[3] * t[2],
                  q[0] * t[2] - q[1] * t[3] + q[2] * t[0] + q[3] * t[1],
                  q[0] * t[3] + q[1] * t[2] - q[2] * t[1] + q[3] * t[0]]
        return {"q": turned, "Omega": W}
