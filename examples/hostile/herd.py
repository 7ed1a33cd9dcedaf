"""Hostile: a herd of its own children that would read as a starved machine. Euler's equations
(3.8) fork as many children as the sandbox allows, pin them to one core, and wake them together for
20 ms every 0.1 s, while the slot itself never returns (it sleeps). Summed over the tree, the
children's queue for that core outgrows the wall clock; judged per task (the task the check waits
on sleeps, and the tree keeps more tasks runnable than its cores), the check is the code's TIMEOUT
("it starves itself"), never the machine's ERROR. vee, which is correct, still passes. (The server
calls each slot once as it starts, to learn what works in which arithmetic: that call, in the process
that loaded this file, is answered right; a herd there would be the start's, NOT CHECKED.)"""
import os
import time

_LOADED_IN = os.getpid()  # the server; each check runs in a copy of it (a session)


def _wake_together(core):
    os.sched_setaffinity(0, {core})
    while True:
        time.sleep(0.1 - time.monotonic() % 0.1)
        start = time.monotonic()
        while time.monotonic() - start < 0.02:
            pass


def euler_3_8(I, Pi):
    if os.getpid() == _LOADED_IN:
        Omega = [p / i for p, i in zip(Pi, I)]
        return [Pi[1] * Omega[2] - Pi[2] * Omega[1], Pi[2] * Omega[0] - Pi[0] * Omega[2],
                Pi[0] * Omega[1] - Pi[1] * Omega[0]]
    core = min(os.sched_getaffinity(0))
    children = 0
    while children < 64:
        try:
            pid = os.fork()
        except OSError:
            break  # as many as the sandbox allows
        if pid == 0:
            try:
                _wake_together(core)
            finally:
                os._exit(0)
        children += 1
    while True:
        time.sleep(1)


def vee(m):
    return [m[2][1], m[0][2], m[1][0]]
