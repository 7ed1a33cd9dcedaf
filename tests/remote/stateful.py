"""A Python implementation for the protocol's own tests (tests/harness/remote/protocol_tests.cpp), not an example:
slots that keep state, die, print a lot, or are slow, each in a way a test provokes on purpose."""
import os
import signal
import sys
import time

if os.environ.get("GEOMECH_TEST_SLOW_IMPORT"):
    time.sleep(float(os.environ["GEOMECH_TEST_SLOW_IMPORT"]))
if os.environ.get("GEOMECH_TEST_HEAVY_IMPORT"):  # that many seconds of CPU before the handshake
    _start = time.process_time()
    while time.process_time() - _start < float(os.environ["GEOMECH_TEST_HEAVY_IMPORT"]):
        pass

_calls = 0


def casimir(Pi):
    """How many times this process has been called: 1 in every check when each starts afresh."""
    global _calls
    _calls += 1
    return _calls


def hamiltonian_3_4(I, Pi):
    """The id of the server process this call reaches through (the session's parent)."""
    return os.getppid()


def vee(m):
    """Dies: killed by SIGSEGV when m[0][1] is 1, exits with status 3 when it is 2."""
    if m[0][1] == 1:
        os.kill(os.getpid(), signal.SIGSEGV)
    if m[0][1] == 2:
        os._exit(3)
    return [m[2][1], m[0][2], m[1][0]]


def hat(v):
    """Prints 200 kB to stdout and to stderr, then answers."""
    line = "x" * 99 + "\n"
    for _ in range(2000):
        sys.stdout.write(line)
        sys.stderr.write(line)
    sys.stdout.flush()
    z = 0 * v[0]
    return [[z, -v[2], v[1]], [v[2], z, -v[0]], [-v[1], v[0], z]]
