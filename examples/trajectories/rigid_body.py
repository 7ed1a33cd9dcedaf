#!/usr/bin/env python3
"""A student's rigid body in Python, writing trajectory files for `geomech check-trajectory`.

This is how the trajectory files next to this script were made (plain Python, no packages):

    python3 rigid_body.py            # writes *.txt here

    ../../geomech check-trajectory midpoint_h*.txt --order 2 --preserves casimir,energy,orthogonality
    ../../geomech check-trajectory explicit_euler_h0.01.txt --preserves casimir     # a false claim
    ../../geomech check-trajectory sign_error_h0.01.txt                             # wrong equations
    ../../geomech check-trajectory spherical_lie_euler_h*.txt --order 1             # exact here: a pass

The format (docs/TRAJECTORY_FORMAT.md): a header of '# key: value' lines, then one row per
output time: t, Pi1, Pi2, Pi3 and the 9 entries of O row by row. Print 17 significant digits
(repr of a float does), or the invariants can only be checked to the digits you print.
"""
import math
import os

I = (2.0, 1.5, 1.0)
PI0 = (math.cos(1.1), 0.0, math.sin(1.1))
T_END = 5.0
OUTPUT_EVERY = 0.1


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def hat(w):
    return ((0.0, -w[2], w[1]), (w[2], 0.0, -w[0]), (-w[1], w[0], 0.0))


def matmul(A, B):
    return tuple(tuple(sum(A[i][k] * B[k][j] for k in range(3)) for j in range(3)) for i in range(3))


def inverse(A):
    (a, b, c), (d, e, f), (g, h, i) = A
    det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g)
    return ((
        ((e * i - f * h) / det, (c * h - b * i) / det, (b * f - c * e) / det),
        ((f * g - d * i) / det, (a * i - c * g) / det, (c * d - a * f) / det),
        ((d * h - e * g) / det, (b * g - a * h) / det, (a * e - b * d) / det)))


def cayley(A):
    """(Id - A/2)^-1 (Id + A/2): orthogonal for skew A."""
    minus = tuple(tuple((1.0 if i == j else 0.0) - A[i][j] / 2 for j in range(3)) for i in range(3))
    plus = tuple(tuple((1.0 if i == j else 0.0) + A[i][j] / 2 for j in range(3)) for i in range(3))
    return matmul(inverse(minus), plus)


def euler_rhs(pi, sign=1.0):
    """dPi/dt = Pi x Omega, Omega = I^-1 Pi (3.8). sign=-1 is the classic sign error."""
    omega = tuple(p / i for p, i in zip(pi, I))
    return tuple(sign * c for c in cross(pi, omega))


def midpoint_step(pi, O, h, sign=1.0):
    """Implicit midpoint for Pi (fixed-point iteration), Cayley transform for O."""
    new = pi
    for _ in range(100):
        mid = tuple((a + b) / 2 for a, b in zip(pi, new))
        again = tuple(p + h * r for p, r in zip(pi, euler_rhs(mid, sign)))
        done = max(abs(x - y) for x, y in zip(again, new)) <= 4e-16 * (1 + max(abs(x) for x in pi))
        new = again
        if done:
            break
    omega_mid = tuple((a + b) / 2 / i for a, b, i in zip(pi, new, I))
    return new, matmul(O, cayley(tuple(tuple(h * x for x in row) for row in hat(omega_mid))))


def explicit_euler_step(pi, O, h, sign=1.0):
    omega = tuple(p / i for p, i in zip(pi, I))
    new_pi = tuple(p + h * r for p, r in zip(pi, euler_rhs(pi, sign)))
    dO = matmul(O, hat(omega))
    return new_pi, tuple(tuple(O[i][j] + h * dO[i][j] for j in range(3)) for i in range(3))


def rotation(w, h):
    """exp(h hat(w)) by Rodrigues' formula: the exact rotation about w by the angle h |w|."""
    angle = h * math.sqrt(sum(x * x for x in w))
    if angle == 0.0:
        return ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))
    K = hat(tuple(x * h / angle for x in w))
    K2 = matmul(K, K)
    s, c = math.sin(angle), 1.0 - math.cos(angle)
    return tuple(tuple((1.0 if i == j else 0.0) + s * K[i][j] + c * K2[i][j] for j in range(3)) for i in range(3))


def lie_euler_step(pi, O, h, sign=1.0):
    """Lie-Euler: Omega frozen at the start of the step, both parts moved by its exact rotation,
    Pi <- exp(-h hat(Omega)) Pi and O <- O exp(h hat(Omega)). First order in general; exact for a
    spherical body, whose Omega = Pi / I stays constant (Pi x Omega = 0)."""
    omega = tuple(sign * p / i for p, i in zip(pi, I))
    R = rotation(omega, h)
    new_pi = tuple(sum(R[k][i] * pi[k] for k in range(3)) for i in range(3))  # R^T Pi = exp(-h hat(Omega)) Pi
    return new_pi, matmul(O, R)


def write(name, step, h, method, sign=1.0):
    pi, O = PI0, ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))
    steps = round(T_END / h)
    every = round(OUTPUT_EVERY / h)
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), name)
    with open(path, "w") as f:
        f.write("# geomech-trajectory 1\n")
        f.write("# system: rigid_body\n")
        f.write("# inertia: %r %r %r\n" % I)
        f.write("# step: %r\n" % h)
        f.write("# method: %s\n" % method)
        f.write("# columns: t Pi1 Pi2 Pi3 O11 O12 O13 O21 O22 O23 O31 O32 O33\n")
        f.write("## written by examples/trajectories/rigid_body.py\n")
        for n in range(steps + 1):
            if n % every == 0:
                row = [n * h] + list(pi) + [x for r in O for x in r]
                f.write(" ".join(repr(x) for x in row) + "\n")
            if n < steps:
                pi, O = step(pi, O, h, sign)


if __name__ == "__main__":
    for h in (0.1, 0.05, 0.025, 0.0125):
        write("midpoint_h%s.txt" % h, midpoint_step, h, "implicit midpoint, Cayley for O")
    write("explicit_euler_h0.01.txt", explicit_euler_step, 0.01, "explicit Euler")
    write("sign_error_h0.01.txt", midpoint_step, 0.01, "implicit midpoint with dPi/dt = Omega x Pi", sign=-1.0)
    # A spherical body: Lie-Euler is exact for it, so its error is at round-off at every step size
    # and an order claim is judged "exact for this problem", not "not measurable".
    I = (1.5, 1.5, 1.5)
    for h in (0.1, 0.05, 0.025):
        write("spherical_lie_euler_h%s.txt" % h, lie_euler_step, h, "Lie-Euler (exact rotations), spherical body")
