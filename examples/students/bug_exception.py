"""Buggy: one slot raises (an index error for a 3-vector in spatial_momentum); the others work.
Expected: spatial_momentum properties FAIL (or ERROR) with the Python traceback in the report."""
from correct import *  # noqa: F401,F403

description = "spatial_momentum raises IndexError (examples/students/bug_exception.py)"


def spatial_momentum(O, P):
    return [sum(O[i][k] * P[k] for k in range(4)) for i in range(3)]
