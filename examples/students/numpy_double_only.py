"""Not buggy, but written with numpy: numpy arrays of float64 only carry double precision, so the
server's probing finds these functions work in double but not in mp50 or exact, and the report
says what that misses. Expected: PASS (double checks), mp50/exact NOT PROVIDED with the reason."""
import numpy as np

description = "numpy implementation, double only (examples/students/numpy_double_only.py)"


def hat(v):
    v = np.asarray(v, dtype=float)
    return np.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])


def vee(m):
    m = np.asarray(m, dtype=float)
    return np.array([m[2, 1], m[0, 2], m[1, 0]])


def euler_3_8(I, P):
    P = np.asarray(P, dtype=float)
    return np.cross(P, P / np.asarray(I, dtype=float))


def hamiltonian_3_4(I, P):
    P = np.asarray(P, dtype=float)
    return 0.5 * float(P @ (P / np.asarray(I, dtype=float)))
