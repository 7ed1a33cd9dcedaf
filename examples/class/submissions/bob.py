"""Week 3, the free rigid body: every assigned function, but Manakov's Omega (2.34) is solved with
numpy.linalg.solve, which works on floats only. In 50 digits and in rationals it raises a TypeError:
a failure of manakov_Omega there (its traceback in the report), and manakov_2_34, which calls it,
fails with it. No integrator.
"""
import numpy as np

description = "Bob: week 3, Manakov's Omega through numpy.linalg.solve"


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return sum((x * y for x, y in zip(a, b)), 0 * a[0])


def matmul(A, B):
    return [[sum((A[i][k] * B[k][j] for k in range(len(B))), 0 * A[0][0]) for j in range(len(B[0]))]
            for i in range(len(A))]


def madd(A, B, s=1):
    return [[a + s * b for a, b in zip(ra, rb)] for ra, rb in zip(A, B)]


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
    w = np.linalg.solve(np.array(K), np.array([M[i][j] for i, j in pairs]))
    W = [[z] * n for _ in range(n)]
    for (i, j), x in zip(pairs, w):
        W[i][j], W[j][i] = x, -x
    return W


def manakov_2_34(A, M):
    W = manakov_Omega(A, M)
    return madd(matmul(M, W), matmul(W, M), -1)
