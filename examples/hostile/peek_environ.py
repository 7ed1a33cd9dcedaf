"""Hostile: a submission that reads the environment and command line of every process it
can see (/proc/*/environ, /proc/*/cmdline) and raises them as its error message, which would print
them into its own report, the one a lecturer hands back. Untrusted mode must leave it nothing
secret to find: the test runs it with a canary in the harness's environment and asserts the canary
never reaches the report; in-process (the control) it does. Like a real attacker, it keeps its
message short (a report shows a message up to 8 KiB, cut beyond): of an environment, only the
variables that look worth stealing."""
import os
import re

WORTH = re.compile(rb"TOKEN|SECRET|KEY|PASS|CANARY|GEOMECH|CI_", re.I)


def ancestors():
    """The processes that started this one, nearest first: the harness is among them."""
    out, pid = [], os.getppid()
    while pid > 1 and len(out) < 16:
        out.append(str(pid))
        try:
            with open("/proc/%d/stat" % pid) as f:
                pid = int(f.read().rsplit(")", 1)[1].split()[1])
        except (OSError, ValueError, IndexError):
            break
    return out


def casimir(Pi):
    found = []
    first = ancestors()
    others = sorted(p for p in os.listdir("/proc") if p.isdigit() and p not in first)
    for pid in first + others:
        if int(pid) == os.getpid():
            continue
        for what in ("environ", "cmdline"):
            try:
                with open("/proc/%s/%s" % (pid, what), "rb") as f:
                    raw = f.read()
                if what == "environ":
                    raw = b"\0".join(v for v in raw.split(b"\0") if WORTH.search(v.split(b"=")[0]))
                text = raw.replace(b"\0", b" ").decode("utf-8", "replace")
                # On one line: the test reads the message up to its first newline, and an
                # environment may hold a value with newlines (CI's did).
                text = text.replace("\r", "\\r").replace("\n", "\\n")
                found.append("%s/%s: %s" % (pid, what, text))
            except OSError:
                pass
    raise RuntimeError("what I could read of other processes: " + " | ".join(found))
