"""Buggy: Omega = I Pi instead of I^-1 Pi in (3.5), and (3.8) built on it.
Expected: omega_3_5 and euler_3_8 properties FAIL."""
from correct import *  # noqa: F401,F403
from correct import cross

description = "Omega computed as I Pi (examples/students/bug_omega_times_inertia.py)"


def omega_3_5(I, P):
    return [p * i for p, i in zip(P, I)]


def euler_3_8(I, P):
    return cross(P, omega_3_5(I, P))
