"""Buggy guard: Euler's equations (3.8) return zero when |Pi| < 1e-9, "to avoid dividing by a tiny
number". Nothing in (3.8) divides by |Pi|: the guard only makes small momenta stand still, which is
wrong for every Pi of size below 1e-9 (the equation is homogeneous: scaled by 2^-40, dPi/dt scales
by 2^-80). Expected: euler_3_8 FAILS (its own check first) on inputs from the small-magnitude regime."""
from correct import *  # noqa: F401,F403
from correct import cross, omega_3_5

description = "Euler's equations with an absolute guard for small Pi (examples/students/bug_tiny_guard.py)"


def euler_3_8(I, P):
    if max(abs(p) for p in P) < 1e-9:
        return [0 * P[0], 0 * P[0], 0 * P[0]]
    return cross(P, omega_3_5(I, P))
