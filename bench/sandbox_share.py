#!/usr/bin/env python3
"""A classmate's share of a core beside a submission whose children each start a session of their own.

    bench/sandbox_share.py GEOMECH [SECONDS] [GEOMECH_BEFORE]

Two untrusted checks run at once, both pinned to the first core: the attacker (a slot that forks 16
children which each call setsid() and then spin) and an honest classmate (tests/blame/slow_hat.py,
CPU-bound). Over SECONDS (default 10) of their overlap, the classmate's sandbox's CPU time, from
/proc, divided by the wall clock is its share of the core; with no attacker beside it, it gets the
whole core. Prints the share, and how many of the attacker's children got a session of their own.
With GEOMECH_BEFORE (another build, say the main branch's), the same with that build, in the same run.
Run as the harness runs (root in CI: each sandbox in its own cgroup; as another user: its own session's
autogroup). A measurement, never a test: it asserts nothing.
"""
import os
import subprocess
import sys
import tempfile
import time

SOURCE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ATTACK = '''import os, time
def euler_3_8(I, Pi):
    if os.getpid() == _LOADED:
        return [0 * I[0]] * 3
    sessions = 0
    for _ in range(16):
        r, w = os.pipe()
        if os.fork() == 0:
            try:
                os.setsid()
                os.write(w, b"s")
            except OSError:
                os.write(w, b"-")
            while True:
                pass
        sessions += os.read(r, 1) == b"s"
    while True:
        time.sleep(1)
_LOADED = os.getpid()
'''


def cpu_of_tag(tag):
    """utime + stime, in seconds, of every process whose environment holds GEOMECH_SANDBOX_TAG=tag."""
    total = 0.0
    tick = os.sysconf("SC_CLK_TCK")
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            env = open("/proc/%s/environ" % pid, "rb").read().split(b"\0")
            if ("GEOMECH_SANDBOX_TAG=" + tag).encode() not in env:
                continue
            fields = open("/proc/%s/stat" % pid).read().rsplit(")", 1)[1].split()
            total += (int(fields[11]) + int(fields[12])) / tick
        except OSError:
            pass
    return total


def sessions_of_tag(tag):
    """How many sessions the processes of that tag are in."""
    sids = set()
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            env = open("/proc/%s/environ" % pid, "rb").read().split(b"\0")
            if ("GEOMECH_SANDBOX_TAG=" + tag).encode() in env:
                sids.add(open("/proc/%s/stat" % pid).read().rsplit(")", 1)[1].split()[3])
        except OSError:
            pass
    return len(sids)


def share(geomech, seconds, attacker, work):
    core = str(min(os.sched_getaffinity(0)))
    env = dict(os.environ, GEOMECH_PYTHON=os.environ.get("GEOMECH_PYTHON", "/usr/bin/python3"))
    common = ["--untrusted", "--scalar", "double", "--jobs", "1", "--timeout", "600", "--case-budget", "0",
              "--cache-dir", os.path.join(work, "cache")]
    procs = []
    if attacker:
        a = os.path.join(work, "attack.py")
        open(a, "w").write(ATTACK)
        procs.append(subprocess.Popen(["taskset", "-c", core, geomech, "check", a, "-p", "definition_euler_3_8",
                                       "--report", os.path.join(work, "ra")] + common,
                                      env=dict(env, GEOMECH_SANDBOX_TAG="share-attacker"), stdout=subprocess.DEVNULL,
                                      stderr=subprocess.DEVNULL))
        time.sleep(3)
    procs.append(subprocess.Popen(["taskset", "-c", core, geomech, "check",
                                   os.path.join(SOURCE, "tests", "blame", "slow_hat.py"), "-p", "hat_is_cross_product",
                                   "--cases", "100000", "--report", os.path.join(work, "rc")] + common,
                                  env=dict(env, GEOMECH_SANDBOX_TAG="share-classmate"), stdout=subprocess.DEVNULL,
                                  stderr=subprocess.DEVNULL))
    time.sleep(3)
    c0, t0 = cpu_of_tag("share-classmate"), time.time()
    time.sleep(seconds)
    c1, t1 = cpu_of_tag("share-classmate"), time.time()
    share.sessions = sessions_of_tag("share-attacker")
    for p in procs:
        p.kill()
        p.wait()
    return (c1 - c0) / (t1 - t0)


def main(argv):
    if not argv:
        sys.exit(__doc__)
    geomech = argv[0]
    seconds = float(argv[1]) if len(argv) > 1 else 10
    builds = [("this build", geomech)] + ([("before", argv[2])] if len(argv) > 2 else [])
    for name, g in builds:
        with tempfile.TemporaryDirectory() as work:
            alone = share(g, seconds, False, work)
            beside = share(g, seconds, True, work)
        print("%s: the classmate's share of the core alone %.0f%%, beside 16 children that try setsid() %.0f%% "
              "(the attacker's processes in %d sessions)" % (name, 100 * alone, 100 * beside, share.sessions))


if __name__ == "__main__":
    main(sys.argv[1:])
