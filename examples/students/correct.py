"""A correct Python implementation of every slot (examples/students/correct.py).

Check it with   ./geomech check examples/students/correct.py

Every function is written generically: the harness calls it with Python floats (double),
mpmath.mpf numbers at 50 digits (mp50) and fractions.Fraction (exact). So no math.sqrt, no float
literals like 0.5 (write x / 2), and for sin/cos the helpers below pick math or mpmath.
Vectors arrive as lists, matrices as lists of rows; return lists, tuples or numpy arrays.
"""
import math
from fractions import Fraction

import mpmath

description = "a correct Python implementation (examples/students/correct.py)"


def _cos(x):
    return math.cos(x) if isinstance(x, float) else mpmath.cos(x)


def _sin(x):
    return math.sin(x) if isinstance(x, float) else mpmath.sin(x)


# ---- small linear algebra on lists ------------------------------------------------------------------

def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return sum((x * y for x, y in zip(a, b)), 0 * a[0])


def matmul(A, B):
    return [[sum((A[i][k] * B[k][j] for k in range(len(B))), 0 * A[0][0]) for j in range(len(B[0]))]
            for i in range(len(A))]


def matvec(A, v):
    return [dot(row, v) for row in A]


def transpose(A):
    return [list(r) for r in zip(*A)]


def madd(A, B, s=1):
    return [[a + s * b for a, b in zip(ra, rb)] for ra, rb in zip(A, B)]


def mscale(A, s):
    return [[a * s for a in r] for r in A]


def zeros(n, m, like):
    return [[0 * like for _ in range(m)] for _ in range(n)]


def identity(n, like):
    return [[like ** 0 if i == j else 0 * like for j in range(n)] for i in range(n)]


def lu(A):
    """LU factorisation with partial pivoting, (rows, pivots): solve_lu(f, b) then costs O(n^2)."""
    n = len(A)
    M = [list(r) for r in A]
    perm = list(range(n))
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(M[r][c]))
        M[c], M[p] = M[p], M[c]
        perm[c], perm[p] = perm[p], perm[c]
        for r in range(c + 1, n):
            f = M[r][c] / M[c][c]
            M[r][c] = f
            for k in range(c + 1, n):
                M[r][k] = M[r][k] - f * M[c][k]
    return M, perm


def solve_lu(f, b):
    M, perm = f
    n = len(M)
    y = [b[perm[i]] for i in range(n)]
    for r in range(n):
        for k in range(r):
            y[r] = y[r] - M[r][k] * y[k]
    for r in reversed(range(n)):
        for k in range(r + 1, n):
            y[r] = y[r] - M[r][k] * y[k]
        y[r] = y[r] / M[r][r]
    return y


def solve(A, b):
    """Gaussian elimination with partial pivoting (exact for Fraction)."""
    return solve_lu(lu(A), b)


def inverse3(A):
    n = len(A)
    f = lu(A)
    cols = [solve_lu(f, [A[0][0] ** 0 if i == j else 0 * A[0][0] for i in range(n)]) for j in range(n)]
    return transpose(cols)


# ---- so(3) and so(n) ---------------------------------------------------------------------------------

def hat(v):
    z = 0 * v[0]
    return [[z, -v[2], v[1]], [v[2], z, -v[0]], [-v[1], v[0], z]]


def vee(m):
    return [m[2][1], m[0][2], m[1][0]]


def pairing(a, b):
    return sum((x * y for ra, rb in zip(a, b) for x, y in zip(ra, rb)), 0 * a[0][0]) / 2


def hat_n(v, n):
    if len(v) != n * (n - 1) // 2:
        raise ValueError("hat_n: %d coordinates do not make an element of so(%d)" % (len(v), n))
    if n == 2:
        z = 0 * v[0]
        return [[z, -v[0]], [v[0], z]]
    if n == 3:
        return hat(v)
    d = (n - 1) * (n - 2) // 2
    top = hat_n(v[:d], n - 1)
    m = [row + [v[d + i]] for i, row in enumerate(top)]
    m.append([-v[d + i] for i in range(n - 1)] + [0 * v[0]])
    return m


def vee_n(m):
    n = len(m)
    if n == 2:
        return [m[1][0]]
    if n == 3:
        return vee(m)
    return vee_n([row[:n - 1] for row in m[:n - 1]]) + [m[i][n - 1] for i in range(n - 1)]


def lie_hat(g, x):
    if g == "so3":
        return hat_n(x, 3)
    if g == "so4":
        return hat_n(x, 4)
    if g == "sl2":
        return [[x[0], x[1]], [x[2], -x[0]]]
    raise ValueError("unknown algebra " + g)


def lie_vee(g, m):
    if g in ("so3", "so4"):
        return vee_n(m)
    return [m[0][0], m[0][1], m[1][0]]


def _bracket(g, a, b):
    A, B = lie_hat(g, a), lie_hat(g, b)
    return lie_vee(g, madd(matmul(A, B), matmul(B, A), -1))


_structure = {}


def structure_constants(g, d):
    """The non-zero c^i_jk of [e_j, e_k] = c^i_jk e_i, as (i, j, k, c) with integer c: they depend
    on the algebra only, so they are computed once per algebra (in integers, exactly)."""
    if (g, d) not in _structure:
        e = [[1 if i == j else 0 for i in range(d)] for j in range(d)]
        _structure[(g, d)] = [(i, j, k, c) for j in range(d) for k in range(d)
                              for i, c in enumerate(_bracket(g, e[j], e[k])) if c != 0]
    return _structure[(g, d)]


def ad_star(g, xi, mu):
    # (ad*_xi mu)_k = xi^j mu_i c^i_jk with [e_j, e_k] = c^i_jk e_i
    out = [0 * xi[0] for _ in xi]
    for i, j, k, c in structure_constants(g, len(xi)):
        out[k] = out[k] + c * xi[j] * mu[i]
    return out


def so4_bracket_R6(a, b):
    u1, v1, u2, v2 = a[:3], a[3:], b[:3], b[3:]
    return [x + y for x, y in zip(cross(u1, u2), cross(v1, v2))] + \
           [x - y for x, y in zip(cross(u1, v2), cross(u2, v1))]


def ad_star_so4_R6(xi, mu):
    xu, xv, mu_u, mu_v = xi[:3], xi[3:], mu[:3], mu[3:]
    return [x + y for x, y in zip(cross(mu_u, xu), cross(mu_v, xv))] + \
           [x + y for x, y in zip(cross(mu_u, xv), cross(mu_v, xu))]


# ---- Euler's equations ----------------------------------------------------------------------------

def euler_2_1(I, W):
    return [(I[(i + 1) % 3] - I[(i + 2) % 3]) * W[(i + 1) % 3] * W[(i + 2) % 3] / I[i] for i in range(3)]


def euler_2_2(I, W):
    IW = [a * b for a, b in zip(I, W)]
    return [c / i for c, i in zip(cross(IW, W), I)]


def euler_3_7(I, P):
    return [(1 / I[(i + 2) % 3] - 1 / I[(i + 1) % 3]) * P[(i + 1) % 3] * P[(i + 2) % 3] for i in range(3)]


def omega_3_5(I, P):
    return [p / i for p, i in zip(P, I)]


def euler_3_8(I, P):
    return cross(P, omega_3_5(I, P))


def euler_matrix_2_12(I, Pi_hat):
    W = hat(omega_3_5(I, vee(Pi_hat)))
    return madd(matmul(Pi_hat, W), matmul(W, Pi_hat), -1)


# ---- Lagrangian, Legendre, Hamiltonian -------------------------------------------------------------

def lagrangian_2_5(I, W):
    return dot(W, legendre_3_1(I, W)) / 2


def lagrangian_2_13(I, W_hat):
    return pairing(hat(legendre_3_1(I, vee(W_hat))), W_hat) / 2


def legendre_3_1(I, W):
    return [i * w for i, w in zip(I, W)]


def hamiltonian_3_3(I, P):
    W = omega_3_5(I, P)
    return dot(P, W) - lagrangian_2_5(I, W)


def hamiltonian_3_4(I, P):
    return dot(P, omega_3_5(I, P)) / 2


def hamiltonian_2_21(I, Pi_hat):
    W_hat = hat(omega_3_5(I, vee(Pi_hat)))
    return pairing(Pi_hat, W_hat) - lagrangian_2_13(I, W_hat)


def casimir(Pi):
    return dot(Pi, Pi) / 2


# ---- brackets ------------------------------------------------------------------------------------

def lie_poisson_2_23(Pi_hat, df, dh):
    return -pairing(Pi_hat, madd(matmul(df, dh), matmul(dh, df), -1))


def lie_poisson_3_6(P, df, dh):
    return -dot(P, cross(df, dh))


def nambu_3_13(dc, df, dh):
    return -dot(dc, cross(df, dh))


def nambu_motion_3_14(dc, dh):
    return cross(dc, dh)


def canonical_bracket(dfdq, dfdp, dhdq, dhdp):
    return dot(dfdq, dhdp) - dot(dfdp, dhdq)


def nambu_3_16(a, x):
    return [-a[0] * a[2] * x[1] * x[2], -a[1] * a[2] * x[2] * x[0], a[0] * a[1] * x[0] * x[1]]


# ---- momentum map, Clebsch, reconstruction, inertia ---------------------------------------------------

def momentum_map(q, p):
    return cross(p, q)


def clebsch_3_21(I, Q, P):
    W = omega_3_5(I, cross(P, Q))
    return cross(Q, W), cross(P, W)


def reconstruction_2_10(O, W):
    return matmul(O, hat(W))


def spatial_momentum(O, P):
    return matvec(O, P)


def inertia_space(O, I):
    return matmul(matmul(O, [[I[i] if i == j else 0 * I[0] for j in range(3)] for i in range(3)]), transpose(O))


def inertia_tensor_2_3(m, X):
    if len(X) != 3 or any(len(r) != len(m) for r in X):
        raise ValueError("X must be 3 x N with N = number of masses")
    T = zeros(3, 3, m[0])
    for k in range(len(m)):
        x = [X[0][k], X[1][k], X[2][k]]
        r2 = dot(x, x)
        for i in range(3):
            for j in range(3):
                T[i][j] += m[k] * ((r2 if i == j else 0 * r2) - x[i] * x[j])
    return T


def inertia_bilinear_2_3(m, X, a, b):
    s = 0 * a[0]
    for k in range(len(m)):
        x = [X[0][k], X[1][k], X[2][k]]
        s += m[k] * dot(cross(a, x), cross(b, x))
    return s


# ---- Manakov on so(n) -----------------------------------------------------------------------------

def manakov_M(A, W):
    return madd(matmul(A, W), matmul(W, A))


_manakov_lu = {}


def manakov_Omega(A, M):
    """Omega in so(n) from A Omega + Omega A = M (2.34), M in so(n): a linear system in the n(n-1)/2
    entries Omega_ij, i < j (Omega is skew), one equation per entry M_ij, i < j. A flow calls this
    with one body A many times: the factorisation of the system for the last A (the key holds its
    entries and their type) is kept, so a call with that A costs one O(n^4) solve."""
    n = len(A)
    pairs = [(i, j) for i in range(n) for j in range(i + 1, n)]
    key = (type(A[0][0]), tuple(tuple(r) for r in A))
    if key not in _manakov_lu:
        z = 0 * A[0][0]
        col = {p: c for c, p in enumerate(pairs)}

        def add(row, k, l, a):  # row += a * Omega_kl, with Omega_kl = -Omega_lk
            if k < l:
                row[col[(k, l)]] += a
            elif l < k:
                row[col[(l, k)]] -= a

        K = []
        for i, j in pairs:
            row = [z] * len(pairs)
            for k in range(n):
                add(row, k, j, A[i][k])  # (A Omega)_ij
                add(row, i, k, A[k][j])  # (Omega A)_ij
            K.append(row)
        _manakov_lu.clear()
        _manakov_lu[key] = lu(K)
    w = solve_lu(_manakov_lu[key], [M[i][j] for i, j in pairs])
    W = [[0 * A[0][0]] * n for _ in range(n)]
    for (i, j), x in zip(pairs, w):
        W[i][j], W[j][i] = x, -x
    return [list(r) for r in W]


def manakov_2_34(A, M):
    W = manakov_Omega(A, M)
    return madd(matmul(M, W), matmul(W, M), -1)


def manakov_lagrangian(A, W):
    WAW = matmul(matmul(W, A), W)
    return -sum((WAW[i][i] for i in range(len(W))), 0 * W[0][0]) / 2


def manakov_clebsch_3_23(A, Q, P):
    M = madd(matmul(transpose(Q), P), matmul(transpose(P), Q), -1)
    W = manakov_Omega(A, M)
    return matmul(Q, W), matmul(P, W)


# ---- integrators ----------------------------------------------------------------------------------

def _cayley(A):
    n = len(A)
    Id = identity(n, A[0][0])
    return matmul(inverse3(madd(Id, mscale(A, A[0][0] ** 0 / 2), -1)), madd(Id, mscale(A, A[0][0] ** 0 / 2)))


class Midpoint:
    """Implicit midpoint for Pi (fixed-point iteration), Cayley transform for O."""
    name = "midpoint"
    claims = {"order": 2, "symmetric": True, "casimir": True, "energy": True, "orthogonality": True}

    @staticmethod
    def rigid_body_step(I, x, h):
        Pi, O = x["Pi"], x["O"]
        eps = 2.0 ** -52 if isinstance(h, float) else mpmath.mpf(2) ** -(mpmath.mp.prec - 1)
        scale = max(abs(p) for p in Pi)  # relative: the same step in any units
        nxt = list(Pi)
        for _ in range(200):
            mid = [(a + b) / 2 for a, b in zip(Pi, nxt)]
            again = [p + h * d for p, d in zip(Pi, euler_3_8(I, mid))]
            change = max(abs(a - b) for a, b in zip(again, nxt))
            nxt = again
            if change <= 8 * eps * scale:
                break
        W = omega_3_5(I, [(a + b) / 2 for a, b in zip(Pi, nxt)])
        return {"Pi": nxt, "O": matmul(O, _cayley(mscale(hat(W), h)))}


class Splitting:
    """Strang splitting into three exactly solved rotations: a Poisson map."""
    name = "lie_poisson_splitting"
    claims = {"order": 2, "symmetric": True, "casimir": True, "orthogonality": True, "poisson": True}

    @staticmethod
    def _rotation(axis, angle):
        j, k = (axis + 1) % 3, (axis + 2) % 3
        R = identity(3, angle)
        c, s = _cos(angle), _sin(angle)
        R[j][j], R[j][k], R[k][j], R[k][k] = c, -s, s, c
        return R

    @staticmethod
    def _flow(axis, I, Pi, O, t):
        angle = t * Pi[axis] / I[axis]
        return matvec(Splitting._rotation(axis, -angle), Pi), matmul(O, Splitting._rotation(axis, angle))

    @staticmethod
    def rigid_body_step(I, x, h):
        Pi, O = x["Pi"], x["O"]
        for axis, t in ((0, h / 2), (1, h / 2), (2, h), (1, h / 2), (0, h / 2)):
            Pi, O = Splitting._flow(axis, I, Pi, O, t)
        return Pi, O
