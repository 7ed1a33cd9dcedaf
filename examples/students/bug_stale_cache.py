"""Buggy fast path: manakov_Omega remembers the factorisation it computed the first time for each
dimension n, to avoid solving the n^2 x n^2 system again; it forgets that the system depends on A.
Right for the first A of each n, wrong for every other body. Expected: manakov_Omega FAILS (its own
check first), and manakov_2_34 with it."""
from correct import *  # noqa: F401,F403
from correct import madd, matmul, solve

description = "manakov_Omega cached by dimension, not by body (examples/students/bug_stale_cache.py)"

_inverse_by_n = {}  # n -> the inverse of the system of the first A seen


def _system(A):
    n = len(A)
    z = 0 * A[0][0]
    K = [[z] * (n * n) for _ in range(n * n)]
    for i in range(n):
        for j in range(n):
            for k in range(n):
                K[i * n + j][k * n + j] += A[i][k]
                K[i * n + j][i * n + k] += A[k][j]
    return K


def manakov_Omega(A, M):
    n = len(A)
    if n not in _inverse_by_n:
        K = _system(A)
        one = A[0][0] ** 0
        cols = [solve(K, [one if i == j else 0 * one for i in range(n * n)]) for j in range(n * n)]
        _inverse_by_n[n] = [list(r) for r in zip(*cols)]
    Kinv = _inverse_by_n[n]
    m = [M[i][j] for i in range(n) for j in range(n)]
    w = [sum((Kinv[r][c] * m[c] for c in range(n * n)), 0 * m[0]) for r in range(n * n)]
    return [[w[i * n + j] for j in range(n)] for i in range(n)]


def manakov_2_34(A, M):
    W = manakov_Omega(A, M)
    return madd(matmul(M, W), matmul(W, M), -1)
