"""Limited: the Hamiltonian multiplies by the float literal 0.5, so with Fractions the result is a
float, not exact (with mpmath.mpf it stays an mpf, 0.5 being exact in binary). Expected: PASS,
hamiltonian_3_4 is not checked in exact and the report says why (a Python float)."""
from correct import *  # noqa: F401,F403
from correct import dot, omega_3_5

description = "hamiltonian_3_4 with a float literal (examples/students/bug_exact_float.py)"


def hamiltonian_3_4(I, P):
    return 0.5 * dot(P, omega_3_5(I, P))
