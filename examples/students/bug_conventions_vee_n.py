"""Buggy, in the conventions of other_conventions.py: vee_n reads the entries above the diagonal column
by column, while hat_n writes them row by row. Both orders are valid choices, but the two functions
must agree: they do for n = 2 and 3 and not from n = 4 on. Expected: definition_vee_n fails in the
coordinates of the file's own hat_n, naming vee_n."""
from other_conventions import *  # noqa: F401,F403

description = "vee_n reading so(n) column by column (examples/students/bug_conventions_vee_n.py)"


def vee_n(m):
    n = len(m)
    return [m[i][j] for j in range(n) for i in range(j)]
