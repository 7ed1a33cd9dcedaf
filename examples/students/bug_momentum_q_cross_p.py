"""Buggy: the momentum map written J = q x p instead of the notes' J = p x q (sign of J).
Expected: properties of momentum_map FAIL; everything else passes."""
from correct import *  # noqa: F401,F403
from correct import cross

description = "momentum map with the wrong orientation, J = q x p (examples/students/bug_momentum_q_cross_p.py)"


def momentum_map(q, p):
    return cross(q, p)
