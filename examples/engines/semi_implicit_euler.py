"""Semi-implicit Euler as physics engines write it, in the state forms engines keep.

An engine steps the angular velocity first (explicitly, with the gyroscopic term), then turns the
attitude with the new angular velocity and renormalises its quaternion. Each integrator below keeps
its state in another form and says so in `state` (docs/STUDENTS.md, "State forms"); the suite
converts to the notes' (Pi, O) with I, and this file converts nothing to them. The conversions an
engine does inside its step (world to body and back) are its own, as in an engine.

    ./geomech check examples/engines/semi_implicit_euler.py

Each integrator claims what the method does: order 1, and its attitude kept exactly on SO(3)
(unit_quaternion for a quaternion, renormalised every step; orthogonality for a matrix, turned by an
exact rotation). Written for floats, as an engine is: `precision` says so, with the reason.
"""
import math

description = "semi-implicit Euler in an engine's state forms (quaternion, omega, Omega, pi)"


# ---- small vector algebra on lists, as an engine has it --------------------------------------------

def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def matvec(M, v):
    return [sum(M[i][k] * v[k] for k in range(3)) for i in range(3)]


def tmatvec(M, v):  # M^T v
    return [sum(M[k][i] * v[k] for k in range(3)) for i in range(3)]


def qmul(a, b):  # Hamilton's product of (w, x, y, z) quaternions
    return [a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
            a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
            a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
            a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]]


def normalised(q):
    n = math.sqrt(sum(c * c for c in q))
    return [c / n for c in q]


def rotation(q):  # the rotation matrix of a unit quaternion (w, x, y, z): body -> world
    w, x, y, z = q
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]


def axis_angle(v, h):  # the rotation matrix exp(h hat(v)) (Rodrigues)
    a = math.sqrt(sum(c * c for c in v))
    if a == 0:
        return [[1.0 if i == j else 0.0 for j in range(3)] for i in range(3)]
    k = [c / a for c in v]
    s, c = math.sin(h * a), 1 - math.cos(h * a)
    K = [[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]]
    K2 = [[sum(K[i][m] * K[m][j] for m in range(3)) for j in range(3)] for i in range(3)]
    return [[(1.0 if i == j else 0.0) + s * K[i][j] + c * K2[i][j] for j in range(3)] for i in range(3)]


def matmul(A, B):
    return [[sum(A[i][m] * B[m][j] for m in range(3)) for j in range(3)] for i in range(3)]


def body_velocity_step(I, W, h):
    """Omega <- Omega + h I^-1 ((I Omega) x Omega): Euler's equations (2.2), explicitly."""
    L = [I[k] * W[k] for k in range(3)]
    g = cross(L, W)
    return [W[k] + h * g[k] / I[k] for k in range(3)]


def turn(q, W, h):
    """q <- normalise(q + (h/2) q (0, Omega)): the body's rate turns q on the body's side."""
    dq = qmul(q, [0.0, W[0], W[1], W[2]])
    return normalised([q[k] + h / 2 * dq[k] for k in range(4)])


# ---- the integrators ---------------------------------------------------------------------------------

class WorldOmega:
    """The engine's own form: a quaternion (w, x, y, z) and the world-frame angular velocity omega."""
    name = "semi_implicit_world_omega"
    state = "quaternion_wxyz omega"
    precision = "double"
    precision_reason = "written as an engine is, on floats with math.sqrt"
    claims = {"order": 1, "unit_quaternion": True}

    @staticmethod
    def rigid_body_step(I, x, h):
        q, omega = x["q"], x["omega"]
        R = rotation(q)
        W = body_velocity_step(I, tmatvec(R, omega), h)   # world -> body: Omega = R^T omega
        q = turn(q, W, h)
        return {"q": q, "omega": matvec(rotation(q), W)}   # body -> world with the new attitude


class BodyOmegaXYZW:
    """A quaternion stored (x, y, z, w), as in Bullet or Eigen's storage, and the body's Omega."""
    name = "semi_implicit_body_Omega_xyzw"
    state = "quaternion_xyzw Omega"
    precision = "double"
    precision_reason = "written as an engine is, on floats with math.sqrt"
    claims = {"order": 1, "unit_quaternion": True}

    @staticmethod
    def rigid_body_step(I, x, h):
        x_, y_, z_, w_ = x["q"]
        W = body_velocity_step(I, x["Omega"], h)
        w, qx, qy, qz = turn([w_, x_, y_, z_], W, h)
        return {"q": [qx, qy, qz, w], "Omega": W}


class MatrixSpatialMomentum:
    """A rotation matrix and the spatial angular momentum pi, which a free body keeps."""
    name = "semi_implicit_matrix_pi"
    state = "matrix pi"
    precision = "double"
    precision_reason = "written as an engine is, on floats with math.sqrt"
    claims = {"order": 1, "orthogonality": True}

    @staticmethod
    def rigid_body_step(I, x, h):
        O, pi = x["O"], x["pi"]
        W = [c / I[k] for k, c in enumerate(tmatvec(O, pi))]   # Omega = I^-1 O^T pi
        W = body_velocity_step(I, W, h)
        O = matmul(O, axis_angle(W, h))
        return {"O": O, "pi": matvec(O, [I[k] * W[k] for k in range(3)])}   # pi = O I Omega, new O
