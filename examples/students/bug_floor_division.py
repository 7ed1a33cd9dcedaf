"""Buggy: `//` is floor division in Python 3, not the `/` of the notes. The Casimir (2.27)
c = |Pi|^2 / 2 is written `dot(Pi, Pi) // 2`, which rounds down to a whole number (for floats,
mpmath numbers and Fractions alike). Expected: casimir FAILS (its own check first)."""
from correct import *  # noqa: F401,F403
from correct import dot

description = "Casimir with floor division // (examples/students/bug_floor_division.py)"


def casimir(Pi):
    return dot(Pi, Pi) // 2
