"""Hostile (issue 34): a submission that reads the environment and command line of every process it
can see (/proc/*/environ, /proc/*/cmdline) and raises them as its error message, which would print
them into its own report, the one a lecturer hands back. Untrusted mode must leave it nothing
secret to find: the test runs it with a canary in the harness's environment and asserts the canary
never reaches the report; in-process (the control) it does."""
import os


def casimir(Pi):
    found = []
    for pid in sorted(os.listdir("/proc")):
        if not pid.isdigit() or int(pid) == os.getpid():
            continue
        for what in ("environ", "cmdline"):
            try:
                with open("/proc/%s/%s" % (pid, what), "rb") as f:
                    text = f.read().replace(b"\0", b" ").decode("utf-8", "replace")
                # On one line: the test reads the message up to its first newline, and an
                # environment may hold a value with newlines (CI's did).
                text = text.replace("\r", "\\r").replace("\n", "\\n")
                found.append("%s/%s: %s" % (pid, what, text))
            except OSError:
                pass
    raise RuntimeError("what I could read of other processes: " + " | ".join(found))
