"""Hostile: more memory than the sandbox's total, held by several processes at once, each within
the size one process may have. Casimir's slot forks three children that each fill 200 MiB and hold
it, and raises how many held theirs together. Checked with --memory-limit 600: a limit per process
(an address space each) lets all three hold 600 MiB and more; the sandbox's memory total (a cgroup) lets at
most two, and the kernel kills what goes past it. Either way the check is the code's."""
import os
import time

MIB = 200


def casimir(Pi):
    held = []
    for _ in range(3):
        r, w = os.pipe()
        pid = os.fork()
        if pid == 0:
            os.close(r)
            block = b"x" * (MIB << 20)  # every page written: resident
            os.write(w, b"1")
            time.sleep(30)
            os._exit(len(block) & 0)
        os.close(w)
        if os.read(r, 1) == b"1":
            held.append(pid)
        os.close(r)
    alive = [p for p in held if os.waitpid(p, os.WNOHANG) == (0, 0)]
    raise RuntimeError("%d children held %d MiB each at once (%d MiB)" % (len(alive), MIB, len(alive) * MIB))
