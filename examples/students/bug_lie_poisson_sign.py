"""Buggy: the Lie-Poisson bracket (3.6) without its minus sign, {f,h} = +Pi . df x dh.
Expected: lie_poisson_3_6 properties FAIL."""
from correct import *  # noqa: F401,F403
from correct import cross, dot

description = "Lie-Poisson bracket with the wrong sign (examples/students/bug_lie_poisson_sign.py)"


def lie_poisson_3_6(P, df, dh):
    return dot(P, cross(df, dh))
