"""Buggy, in the conventions of other_conventions.py (so(n) coordinates row by row): so(2) written as
[[0, v], [v, 0]], a symmetric matrix, not an element of so(2). Expected: definition_hat_n fails (its
first message names hat_n and says the matrix of e1 is not an elementary skew matrix); the
coordinates themselves are a valid choice, and the other n pass."""
import other_conventions
from other_conventions import *  # noqa: F401,F403

description = "hat_n with so(2) symmetric (examples/students/bug_conventions_hat_n.py)"


def hat_n(v, n):
    if n == 2:
        z = 0 * v[0]
        return [[z, v[0]], [v[0], z]]
    return other_conventions.hat_n(v, n)
