"""Buggy for exact and 50-digit checks: the Hamiltonian multiplies by the float 0.5, so the
result is only double precision. Expected: hamiltonian_3_4 checked in double only, the report
notes why it is not available in mp50 and exact."""
from correct import *  # noqa: F401,F403
from correct import dot, omega_3_5

description = "hamiltonian_3_4 with a float literal (examples/students/bug_exact_float.py)"


def hamiltonian_3_4(I, P):
    return 0.5 * dot(P, omega_3_5(I, P))
