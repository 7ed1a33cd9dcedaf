"""The grader's machine is checked once, first, and its faults are never a student's grade.

    python3 grader_machine.py GEOMECH SOURCE_DIR OUT_DIR

Three faults of a lecturer's or an autograder's machine, each made here on purpose, then fixed:
  cache        the compilers' cache under a folder only its owner may enter (as mktemp -d makes):
               the class run refuses before checking anyone (exit 3), naming the folder and
               `chmod o+x`; with the fix, it checks.
  interpreter  GEOMECH_PYTHON a venv inside such a folder: refused the same way, naming
               GEOMECH_PYTHON; with GEOMECH_PYTHON set to the system's, the student is checked and
               graded. The interpreter is part of a class run's fingerprint: another interpreter
               checks again what an unchanged one resumes.
  sandbox      a bubblewrap that fails as a container's default seccomp profile makes it fail
               (GEOMECH_BWRAP): `geomech self-test` exits 3 with the fix; the Gradescope autograder's
               setup.sh runs it; grade-submission writes no results.json and exits 3 (the platform's
               grader error), never a score.
As root, the sandbox's user is nobody and the first two faults are real; as another user, the
sandbox runs as that user, who owns the folders, and the check must pass instead (the control).
"""
import csv
import os
import shutil
import stat
import subprocess
import sys

GEOMECH, SOURCE, OUT = sys.argv[1:4]
NARROW = ["--scalar", "double", "-p", "definition_hat", "-p", "definition_casimir"]
STUDENT = os.path.join(SOURCE, "examples", "class", "submissions", "alice.py")
ROOT = os.geteuid() == 0
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)


def run(args, env=None, timeout=600):
    e = dict(os.environ)
    e.update(env or {})
    p = subprocess.run([GEOMECH] + args, capture_output=True, text=True, errors="replace", timeout=timeout, env=e)
    return p.returncode, p.stdout + p.stderr


def private_folder(path):
    os.makedirs(path)
    os.chmod(path, stat.S_IRWXU)  # 0700: only its owner may enter
    return path


shutil.rmtree(OUT, ignore_errors=True)
os.makedirs(OUT)
rc, text = run(["self-test", "--no-python"])
if rc == 3 and "does not work on this machine" in text:  # no user namespaces here: nothing to try
    print("this machine has no working sandbox: " + text.strip().splitlines()[-1])
    sys.exit(0 if os.environ.get("GEOMECH_ALLOW_NO_SANDBOX") else 1)
klass = os.path.join(OUT, "class")
os.makedirs(klass)
shutil.copy(STUDENT, os.path.join(klass, "alice.py"))
system_python = {"GEOMECH_PYTHON": "/usr/bin/python3"}

# -- the cache --------------------------------------------------------------------------------
private = private_folder(os.path.join(OUT, "private"))
cache = os.path.join(private, "cache")
report = os.path.join(OUT, "report-cache")
rc, text = run(["check-class", klass, "--report", report, "--cache-dir", cache] + NARROW, env=system_python)
if ROOT:
    check(rc == 3, "cache: a cache out of the sandbox's reach should refuse with exit 3, got %d:\n%s" % (rc, text[-1500:]))
    check("out of the sandbox's reach" in text and "chmod o+x " + private in text,
          "cache: the refusal should name the folder and its fix:\n" + text[-1500:])
    check(not os.path.exists(os.path.join(report, "summary.md")), "cache: nobody may be checked on a broken machine")
    os.chmod(private, stat.S_IRWXU | stat.S_IXOTH)  # the fix the message gives
    rc, text = run(["check-class", klass, "--report", report, "--cache-dir", cache] + NARROW, env=system_python)
check(rc in (0, 1) and os.path.exists(os.path.join(report, "summary.md")),
      "cache: with a reachable cache the class should be checked (exit %d):\n%s" % (rc, text[-1500:]))

# -- the interpreter --------------------------------------------------------------------------
hidden = private_folder(os.path.join(OUT, "private-venv"))
subprocess.run(["/usr/bin/python3", "-m", "venv", "--without-pip", "--system-site-packages", os.path.join(hidden, "venv")],
               check=True)
report = os.path.join(OUT, "report-python")
grades = os.path.join(OUT, "grades.csv")
args = ["check-class", klass, "--report", report, "--grades", grades] + NARROW
rc, text = run(args, env={"GEOMECH_PYTHON": os.path.join(hidden, "venv", "bin", "python")})
if ROOT:
    check(rc == 3, "interpreter: an interpreter the sandbox cannot read should refuse with exit 3, got %d:\n%s" % (rc, text[-1500:]))
    check("GEOMECH_PYTHON" in text and "cannot be shown to the sandbox" in text,
          "interpreter: the refusal should name GEOMECH_PYTHON:\n" + text[-1500:])
    check(not os.path.exists(grades), "interpreter: no gradebook may be written when nobody could be checked")
rc, text = run(args, env=system_python)  # the fix the message gives
check(rc in (0, 1), "interpreter: with the system's python3 the class should be checked (exit %d):\n%s" % (rc, text[-1500:]))
rows = list(csv.reader(open(grades, encoding="utf-8"))) if os.path.exists(grades) else []
alice = [r for r in rows if r and r[0] == "alice"]
check(alice and len(alice[0]) > 4 and alice[0][4] != "", "interpreter: the gradebook should hold alice's grade: %r" % rows)
# The same interpreter resumes; another one checks again.
rc, text = run(args, env=system_python)
check("1 of 1 implementations are unchanged" in text, "interpreter: the same interpreter should resume:\n" + text[-1500:])
public = os.path.join(OUT, "public-venv")
subprocess.run(["/usr/bin/python3", "-m", "venv", "--without-pip", "--system-site-packages", public], check=True)
rc, text = run(args, env={"GEOMECH_PYTHON": os.path.join(public, "bin", "python")})
check(rc in (0, 1) and "unchanged" not in text,
      "interpreter: another interpreter should check the student again (exit %d):\n%s" % (rc, text[-1500:]))

# -- a sandbox that cannot start, in an autograder ---------------------------------------------
fake = os.path.join(OUT, "bwrap-in-a-container")
with open(fake, "w") as f:
    f.write("#!/bin/sh\necho 'bwrap: No permissions to creating new namespace, likely because the kernel does not "
            "allow non-privileged user namespaces.' >&2\nexit 1\n")
os.chmod(fake, 0o755)
broken = {"GEOMECH_BWRAP": fake, "GEOMECH_PYTHON": "/usr/bin/python3"}
rc, text = run(["self-test"], env=broken)
check(rc == 3 and "does not work on this machine" in text, "sandbox: self-test should fail with exit 3 and the fix (exit %d):\n%s" % (rc, text))
rc, text = run(["self-test"], env=system_python)
check(rc == 0, "sandbox: the control, self-test on this machine, should pass (exit %d):\n%s" % (rc, text))
# One untrusted check on that machine: the machine's set-up (exit 3), not the file's (2); the control,
# the same check on this machine, reaches its verdict.
rc, text = run(["check", "--untrusted", STUDENT] + NARROW, env=broken)
check(rc == 3 and "does not work on this machine" in text,
      "sandbox: an untrusted check should fail with the machine's exit 3 (exit %d):\n%s" % (rc, text[-1500:]))
rc, text = run(["check", "--untrusted", STUDENT] + NARROW, env=system_python)
check(rc in (0, 1), "sandbox: the control, an untrusted check on this machine, should end in a verdict (exit %d):\n%s"
      % (rc, text[-1500:]))
ag = os.path.join(OUT, "ag")
rc, text = run(["autograder", "gradescope", ag, "--rubric", os.path.join(SOURCE, "examples", "class", "rubric.json"),
                "--no-zip"] + NARROW)
check(rc == 0, "autograder: it should be written (exit %d):\n%s" % (rc, text[-1500:]))
setup = open(os.path.join(ag, "setup.sh")).read() if os.path.exists(os.path.join(ag, "setup.sh")) else ""
check("geomech self-test" in setup, "autograder: setup.sh should run the self-test, so that a broken image fails to build")
config = [os.path.join(dirpath, n) for dirpath, _, names in os.walk(ag) for n in names if n.endswith(".json") and "autograder" in n]
submission = os.path.join(OUT, "submission")
os.makedirs(submission)
shutil.copy(STUDENT, submission)
results = os.path.join(OUT, "results", "results.json")
check(bool(config), "autograder: its configuration file should be in " + ag)
if config:
    rc, text = run(["grade-submission", "gradescope", "--submission", submission, "--results", results, "--config", config[0]],
                   env=broken)
    check(rc == 3, "grade-submission: a sandbox that cannot start should exit 3 (the platform's grader error), got %d:\n%s" % (rc, text[-1500:]))
    check(not os.path.exists(results), "grade-submission: no results.json (no score) may be written on a broken machine")
    check("GRADER ERROR" in text, "grade-submission: the log should say GRADER ERROR:\n" + text[-1500:])
    rc, text = run(["grade-submission", "gradescope", "--submission", submission, "--results", results, "--config", config[0]],
                   env=system_python)
    check(rc == 0 and os.path.exists(results), "grade-submission: the control on this machine should write results.json (exit %d):\n%s" % (rc, text[-1500:]))

if failures:
    print("\n".join("FAILED: " + f for f in failures))
    sys.exit(1)
print("every fault of the grader's machine was refused with its fix, and nobody was graded for it")
