"""Correct, in other conventions than the suite's documented ones: every choice the notes
leave open is made differently here, and the check must pass with zero failures.

  so(n) in hat_n (every n, n = 3 included): the entries above the diagonal row by row, with sign +,
      so so(2) is [[0, v], [-v, 0]] and so(3) is [[0, v1, v2], [-v1, 0, v3], [-v2, -v3, 0]]
      (the documented ones follow (2.11) at n = 3: [[0, -v3, v2], [v3, 0, -v1], [-v2, v1, 0]]);
  so(3), so(4) in lie_hat: a third choice, the negative of hat_n's, (-1) times each coordinate;
  sl(2, R) in lie_hat: the basis (sigma_z, sigma_x, i sigma_y), (a, b, c) -> [[a, b + c], [b - c, -a]]
      (documented: [[a, b], [c, -a]]);
  ad_star, so4_bracket_R6, ad_star_so4_R6: computed from their definitions in those bases (another
      factorisation than the reference's structure constants and cross products).

Everything else is correct.py's. The suite learns the coordinates from hat_n and lie_hat themselves
(`geomech slots`, "convention"); examples/students/bug_conventions_*.py make one real mistake each
in these same conventions.
"""
from correct import *  # noqa: F401,F403
from correct import madd, matmul

description = "correct, with so(n) coordinates row by row, another so(3)/so(4) basis in lie_hat and the " \
              "Pauli-like basis of sl(2, R) (examples/students/other_conventions.py)"


def _pairs(n):
    return [(i, j) for i in range(n) for j in range(i + 1, n)]


def hat_n(v, n):
    if len(v) != n * (n - 1) // 2:
        raise ValueError("hat_n: %d coordinates do not make an element of so(%d)" % (len(v), n))
    z = 0 * v[0]
    m = [[z] * n for _ in range(n)]
    for k, (i, j) in enumerate(_pairs(n)):
        m[i][j], m[j][i] = v[k], -v[k]
    return m


def vee_n(m):
    return [m[i][j] for i, j in _pairs(len(m))]


def lie_hat(g, x):
    if g in ("so3", "so4"):
        return [[-e for e in row] for row in hat_n(x, 3 if g == "so3" else 4)]
    if g == "sl2":
        a, b, c = x
        return [[a, b + c], [b - c, -a]]
    raise ValueError("unknown algebra " + g)


def lie_vee(g, m):
    if g in ("so3", "so4"):
        return [-e for e in vee_n(m)]
    return [m[0][0], (m[0][1] + m[1][0]) / 2, (m[0][1] - m[1][0]) / 2]


def _unit(d, k, like):
    return [like ** 0 if i == k else 0 * like for i in range(d)]


def _ad_star(hat, vee, xi, mu):
    """<ad*_xi mu, e_k> = <mu, [xi, e_k]>: component k is mu . vee([hat(xi), hat(e_k)])."""
    X = hat(xi)
    out = []
    for k in range(len(xi)):
        E = hat(_unit(len(xi), k, xi[0]))
        c = vee(madd(matmul(X, E), matmul(E, X), -1))
        out.append(sum((a * b for a, b in zip(mu, c)), 0 * mu[0]))
    return out


def ad_star(g, xi, mu):
    return _ad_star(lambda x: lie_hat(g, x), lambda m: lie_vee(g, m), xi, mu)


def so4_bracket_R6(a, b):
    A, B = hat_n(a, 4), hat_n(b, 4)
    return vee_n(madd(matmul(A, B), matmul(B, A), -1))


def ad_star_so4_R6(xi, mu):
    return _ad_star(lambda x: hat_n(x, 4), vee_n, xi, mu)
