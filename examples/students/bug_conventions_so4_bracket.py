"""Buggy, in the conventions of other_conventions.py (so(4) coordinates row by row): the bracket of
R^6 taken as vee([B, A]), the commutator reversed. Expected: definition_so4_bracket_R6 fails in the
file's own coordinates, naming so4_bracket_R6."""
from other_conventions import *  # noqa: F401,F403
from correct import madd, matmul

description = "so4_bracket_R6 with the commutator reversed (examples/students/bug_conventions_so4_bracket.py)"


def so4_bracket_R6(a, b):
    A, B = hat_n(a, 4), hat_n(b, 4)
    return vee_n(madd(matmul(B, A), matmul(A, B), -1))
