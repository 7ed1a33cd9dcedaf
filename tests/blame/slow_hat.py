"""An honest, slow implementation for tests/blame.py (not an example): the hat map (2.11), right,
computed after 10 ms of CPU a call. Alone its check passes; starved of CPU by busy processes outside
its sandbox, the check is the machine's ERROR, never the code's."""
import time


def hat(v):
    start = time.process_time()
    while time.process_time() - start < 0.01:
        pass
    z = 0 * v[0]
    return [[z, -v[2], v[1]], [v[2], z, -v[0]], [-v[1], v[0], z]]
