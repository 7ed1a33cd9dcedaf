"""semi_implicit_euler.py with one conversion wrong inside each integrator's step, as wrappers and
engines get them wrong. Each keeps its declared form; the suite names the form in its answer.

- WorldOmega: world -> body with R instead of R^T (Omega = R omega): the step no longer returns its
  own state as h -> 0 ("your step is not consistent in it").
- BodyOmegaXYZW: the body's Omega applied on the world's side of q ((0, Omega) q instead of
  q (0, Omega)): "your quaternion q = (x, y, z, w) turns with the body's Omega on the left".
- MatrixSpatialMomentum: pi rebuilt with the attitude before the turn: "your pi ... follows dpi/dt".
"""
# geomech: beside semi_implicit_euler.py
from semi_implicit_euler import (matvec, tmatvec, qmul, normalised, rotation, axis_angle, matmul,
                                 body_velocity_step)

description = "semi-implicit Euler in an engine's state forms, one conversion wrong in each step"


class WorldOmegaTransposeSlip:
    name = "world_omega_transpose_slip"
    state = "quaternion_wxyz omega"
    precision = "double"
    precision_reason = "written as an engine is, on floats with math.sqrt"
    claims = {"order": 1, "unit_quaternion": True}

    @staticmethod
    def rigid_body_step(I, x, h):
        q, omega = x["q"], x["omega"]
        R = rotation(q)
        W = body_velocity_step(I, matvec(R, omega), h)   # the slip: R omega, not R^T omega
        dq = qmul(q, [0.0, W[0], W[1], W[2]])
        q = normalised([q[k] + h / 2 * dq[k] for k in range(4)])
        return {"q": q, "omega": matvec(rotation(q), W)}


class BodyOmegaOnWorldSide:
    name = "body_Omega_on_world_side"
    state = "quaternion_xyzw Omega"
    precision = "double"
    precision_reason = "written as an engine is, on floats with math.sqrt"
    claims = {"order": 1, "unit_quaternion": True}

    @staticmethod
    def rigid_body_step(I, x, h):
        x_, y_, z_, w_ = x["q"]
        W = body_velocity_step(I, x["Omega"], h)
        q = [w_, x_, y_, z_]
        dq = qmul([0.0, W[0], W[1], W[2]], q)             # the slip: (0, Omega) q is the world's rate
        w, qx, qy, qz = normalised([q[k] + h / 2 * dq[k] for k in range(4)])
        return {"q": [qx, qy, qz, w], "Omega": W}


class MatrixMomentumStaleAttitude:
    name = "matrix_pi_stale_attitude"
    state = "matrix pi"
    precision = "double"
    precision_reason = "written as an engine is, on floats with math.sqrt"
    claims = {"order": 1, "orthogonality": True}

    @staticmethod
    def rigid_body_step(I, x, h):
        O, pi = x["O"], x["pi"]
        W = [c / I[k] for k, c in enumerate(tmatvec(O, pi))]
        W = body_velocity_step(I, W, h)
        turned = matmul(O, axis_angle(W, h))
        return {"O": turned, "pi": matvec(O, [I[k] * W[k] for k in range(3)])}   # the slip: O, not the turned O
