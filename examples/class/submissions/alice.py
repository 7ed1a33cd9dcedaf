"""Week 3, the free rigid body: every assigned function, right, and an integrator with its claims.

Alice writes each function once for any scalar (float, mpmath.mpf, fractions.Fraction): no float
literals, no math module, `0 * v[0]` for a zero of the right kind.
"""
import mpmath

description = "Alice: week 3, every assigned function and the implicit midpoint rule"


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return sum((x * y for x, y in zip(a, b)), 0 * a[0])


def matmul(A, B):
    return [[sum((A[i][k] * B[k][j] for k in range(len(B))), 0 * A[0][0]) for j in range(len(B[0]))]
            for i in range(len(A))]


def madd(A, B, s=1):
    return [[a + s * b for a, b in zip(ra, rb)] for ra, rb in zip(A, B)]


def solve(K, b):
    """Gaussian elimination with partial pivoting (exact for Fraction)."""
    n = len(K)
    M = [list(r) + [v] for r, v in zip(K, b)]
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(M[r][c]))
        M[c], M[p] = M[p], M[c]
        for r in range(c + 1, n):
            f = M[r][c] / M[c][c]
            M[r] = [x - f * y for x, y in zip(M[r], M[c])]
    x = [0 * b[0]] * n
    for r in reversed(range(n)):
        x[r] = (M[r][n] - sum((M[r][k] * x[k] for k in range(r + 1, n)), 0 * b[0])) / M[r][r]
    return x


# (2.11): hat(v) w = v x w, and its inverse.
def hat(v):
    z = 0 * v[0]
    return [[z, -v[2], v[1]], [v[2], z, -v[0]], [-v[1], v[0], z]]


def vee(m):
    return [m[2][1], m[0][2], m[1][0]]


# (3.5) Omega = I^-1 Pi and (3.8) dPi/dt = Pi x Omega.
def omega_3_5(I, Pi):
    return [p / i for p, i in zip(Pi, I)]


def euler_3_8(I, Pi):
    return cross(Pi, omega_3_5(I, Pi))


# (3.4) h = Pi . I^-1 Pi / 2 and the Casimir |Pi|^2 / 2.
def hamiltonian_3_4(I, Pi):
    return dot(Pi, omega_3_5(I, Pi)) / 2


def casimir(Pi):
    return dot(Pi, Pi) / 2


# (2.10) dO/dt = O Omega_hat, and the spatial momentum pi = O Pi.
def reconstruction_2_10(O, Omega):
    return matmul(O, hat(Omega))


def spatial_momentum(O, Pi):
    return [dot(row, Pi) for row in O]


# Manakov (2.34): M = A Omega + Omega A, Omega from M, and dM/dt = [M, Omega].
def manakov_M(A, Omega):
    return madd(matmul(A, Omega), matmul(Omega, A))


def manakov_Omega(A, M):
    n = len(A)
    pairs = [(i, j) for i in range(n) for j in range(i + 1, n)]
    col = {p: c for c, p in enumerate(pairs)}
    z = 0 * A[0][0]
    K = []
    for i, j in pairs:  # one equation (A Omega + Omega A)_ij = M_ij per entry above the diagonal
        row = [z] * len(pairs)
        for k in range(n):
            for (a, b), coef in (((k, j), A[i][k]), ((i, k), A[k][j])):
                if a < b:
                    row[col[(a, b)]] += coef
                elif b < a:
                    row[col[(b, a)]] -= coef
        K.append(row)
    w = solve(K, [M[i][j] for i, j in pairs])
    W = [[z] * n for _ in range(n)]
    for (i, j), x in zip(pairs, w):
        W[i][j], W[j][i] = x, -x
    return W


def manakov_2_34(A, M):
    W = manakov_Omega(A, M)
    return madd(matmul(M, W), matmul(W, M), -1)


class Midpoint:
    """The implicit midpoint rule for Pi (fixed-point iteration), the Cayley transform for O."""
    name = "midpoint"
    claims = {"order": 2, "symmetric": True, "casimir": True, "energy": True, "orthogonality": True}

    @staticmethod
    def rigid_body_step(I, x, h):
        Pi, O = x["Pi"], x["O"]
        eps = 2.0 ** -52 if isinstance(h, float) else mpmath.mpf(2) ** -(mpmath.mp.prec - 1)
        scale = max(abs(p) for p in Pi)
        nxt = list(Pi)
        for _ in range(200):
            mid = [(a + b) / 2 for a, b in zip(Pi, nxt)]
            again = [p + h * d for p, d in zip(Pi, euler_3_8(I, mid))]
            change = max(abs(a - b) for a, b in zip(again, nxt))
            nxt = again
            if change <= 8 * eps * scale:
                break
        W = omega_3_5(I, [(a + b) / 2 for a, b in zip(Pi, nxt)])
        # Cayley: (1 - h W_hat / 2)^-1 (1 + h W_hat / 2), solved column by column.
        Wh = [[h * e / 2 for e in r] for r in hat(W)]
        one = h ** 0
        minus = [[(one if i == j else 0 * one) - Wh[i][j] for j in range(3)] for i in range(3)]
        plus = [[(one if i == j else 0 * one) + Wh[i][j] for j in range(3)] for i in range(3)]
        cols = [solve(minus, [plus[i][j] for i in range(3)]) for j in range(3)]
        C = [[cols[j][i] for j in range(3)] for i in range(3)]
        return {"Pi": nxt, "O": matmul(O, C)}
