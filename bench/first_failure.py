#!/usr/bin/env python3
"""Time from a command to the first thing a student can act on: runs the command, reads
its output as it comes, and stops it at the first FIRST FIX or FALSE CLAIM line, printing the time.
The whole run is then one command whose duration is that time, so a timing tool that runs a command
several times (hyperfine, for instance) measures it directly:

    bench/first_failure.py ./geomech check examples/students/bug_floor_division.py
    bench/first_failure.py ./geomech check examples/students/bug_euler_sign.cpp --cache-dir "$(mktemp -d)"

Exit status 0 when such a line came, 1 when the command ended without one."""
import os
import signal
import subprocess
import sys
import time


def stop_session(p):
    """Stops the command and everything it started. Its compilers run in process groups of their own
    (a timeout stops a compiler's whole tree), so killing its group alone would leave them running
    into the next timed run; they all stay in the command's session."""
    def in_session():
        pids = []
        for d in os.listdir("/proc"):
            if d.isdigit():
                try:
                    with open(f"/proc/{d}/stat") as f:
                        fields = f.read().rsplit(")", 1)[1].split()
                except OSError:
                    continue
                # The session id, after the state, ppid and pgrp; a zombie (state Z) is dead already.
                if int(fields[3]) == p.pid and fields[0] != "Z":
                    pids.append(int(d))
        return pids
    while True:
        pids = in_session()
        if not pids:
            break
        for pid in pids:
            try:
                os.kill(pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        if p.poll() is None:
            p.wait()
        time.sleep(0.01)
    p.wait()


def main(argv):
    if not argv:
        sys.exit(__doc__)
    start = time.monotonic()
    p = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True, start_new_session=True)
    for line in p.stdout:
        if "FIRST FIX" in line or "FALSE CLAIM" in line:
            print(f"{time.monotonic() - start:.2f} s to: {line.strip()[:160]}")
            stop_session(p)
            return 0
    p.wait()
    print(f"no FIRST FIX or FALSE CLAIM line in {time.monotonic() - start:.2f} s (exit status {p.returncode})")
    return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
