"""Week 3, begun: the hat map, its inverse and the Casimir, all right, and nothing else yet. Every
check that runs passes, but the assignment asks for eleven functions: INCOMPLETE, not PASS, and a
short report about what is there.
"""

description = "Frank: three of the eleven functions"


def hat(v):
    z = 0 * v[0]
    return [[z, -v[2], v[1]], [v[2], z, -v[0]], [-v[1], v[0], z]]


def vee(m):
    return [m[2][1], m[0][2], m[1][0]]


def casimir(Pi):
    return sum((p * p for p in Pi), 0 * Pi[0]) / 2
