"""Hostile: as many processes as the sandbox lets it have. The Hamiltonian (3.4) forks sleeping
children until a fork fails, and raises how many it got as its error: the check FAILs with that
number (the code's). The sandbox's task count is the kernel's, per user namespace: its own
processes alone, 32 in all (the server and its session among them), whatever the sandbox's user
runs elsewhere on the machine (before, it got 32 more than that user's other processes)."""
import os
import time


def hamiltonian_3_4(I, Pi):
    children = []
    failure = "none"
    while len(children) < 200:
        try:
            pid = os.fork()
        except OSError as e:
            failure = "%s" % e
            break
        if pid == 0:
            time.sleep(60)
            os._exit(0)
        children.append(pid)
    raise RuntimeError("forked %d children, then: %s" % (len(children), failure))
