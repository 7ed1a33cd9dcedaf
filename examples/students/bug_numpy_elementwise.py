"""Buggy: numpy's `*` is the elementwise product, not the matrix product. The reconstruction (2.10)
dO/dt = O Omega_hat is written `O * hat(Omega)` where `O @ hat(Omega)` was meant.
Expected: reconstruction_2_10 FAILS (its own check first); numpy makes it double only."""
import numpy as np

from correct import *  # noqa: F401,F403

description = "reconstruction (2.10) with numpy's elementwise * (examples/students/bug_numpy_elementwise.py)"


def reconstruction_2_10(O, W):
    O = np.asarray(O, dtype=float)
    W_hat = np.array([[0.0, -W[2], W[1]], [W[2], 0.0, -W[0]], [-W[1], W[0], 0.0]])
    return O * W_hat  # should be O @ W_hat
