"""Buggy claim: explicit Euler for Pi (order 1) claiming to preserve the Casimir |Pi|^2.
Expected: the casimir claim FAILS for integrator 'explicit_euler'."""
from correct import euler_3_8, hat, matmul, mscale, madd, identity, omega_3_5

description = "explicit Euler falsely claiming casimir (examples/students/bug_claims_casimir.py)"


class ExplicitEuler:
    name = "explicit_euler"
    claims = {"order": 1, "casimir": True}

    @staticmethod
    def rigid_body_step(I, x, h):
        Pi, O = x["Pi"], x["O"]
        d = euler_3_8(I, Pi)
        W = omega_3_5(I, Pi)
        return {"Pi": [p + h * q for p, q in zip(Pi, d)],
                "O": matmul(O, madd(identity(3, h), mscale(hat(W), h)))}
