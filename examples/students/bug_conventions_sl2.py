"""Buggy, in the conventions of other_conventions.py (sl(2, R) in the basis (sigma_z, sigma_x,
i sigma_y), (a, b, c) -> [[a, b + c], [b - c, -a]]): lie_vee forgets the halves, b = m01 + m10 and
c = m01 - m10. Expected: definition_lie_vee fails in the file's own basis (learned from lie_hat),
naming lie_vee."""
import other_conventions
from other_conventions import *  # noqa: F401,F403

description = "lie_vee without the halves of its sl(2) basis (examples/students/bug_conventions_sl2.py)"


def lie_vee(g, m):
    if g == "sl2":
        return [m[0][0], m[0][1] + m[1][0], m[0][1] - m[1][0]]
    return other_conventions.lie_vee(g, m)
