"""Blame cannot be gamed: a submission cannot pass its own failure off as the grader's machine's.

    python3 blame.py GEOMECH SOURCE_DIR OUT_DIR MODE

Each attack of examples/hostile/ is checked in untrusted mode and charged to the code, and each real
fault of the machine, made here on purpose, stays the machine's (exit status 3, no grade):

  compile  a `#line` naming the sandbox's tool (bwrap: ...) in a file that does not compile
           (line_bwrap.cpp: "does not compile", exit 2) and in one whose exact piece alone does not
           (line_bwrap_exact.cpp: checked, the piece the file's); the control, a stand-in bubblewrap
           that fails for the compile as a broken machine's does: the grader's machine, exit 3.
  herd     a herd of its own pinned children waking together, in Python, C++ and Octave (herd.*):
           TIMEOUT, "it starves itself" (or "it waits", or its CPU time spent), never the machine's
           ERROR; vee still passes.
  limits   forks past the documented limit (fork_count.py: at most 32 tasks in the sandbox, the same
           with the sandbox's user running other processes outside it) and memory past the total
           (memory_total.py, --memory-limit 600: three children of 200 MiB never all held at once,
           as root where a cgroup keeps the total); each the code's FAIL or CRASH, exit 1.
  starved  a really starved check: an honest, slow slot (tests/blame/slow_hat.py) beside busy
           processes outside the sandbox on its core, with the wall guard and the busy limit
           brought within seconds (GEOMECH_TEST_LIMITS): the machine's ERROR, exit 3 in a
           single-file check; the control, alone: PASS.
  class    a class where one student's compile always meets the machine's fault (a stand-in
           bubblewrap failing for that student alone) beside a classmate checked fine: GRADER ERROR
           with no grade in every view (summary.md, the console, grades.csv), exit 3; checked again
           once, then suspect and left to the lecturer, not checked again by a plain run.
"""
import csv
import json
import os
import re
import shutil
import subprocess
import sys
import time

GEOMECH, SOURCE, OUT, MODE = sys.argv[1:5]
GEOMECH, SOURCE, OUT = os.path.abspath(GEOMECH), os.path.abspath(SOURCE), os.path.abspath(OUT)
HOSTILE = os.path.join(SOURCE, "examples", "hostile")
ROOT = os.geteuid() == 0
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
    return cond


def run(args, env=None, timeout=900, cwd=None, prefix=()):
    e = dict(os.environ)
    e.setdefault("GEOMECH_PYTHON", "/usr/bin/python3")  # the system's, which the sandbox can read
    e.update(env or {})
    p = subprocess.run(list(prefix) + [GEOMECH] + args, capture_output=True, text=True, errors="replace",
                       timeout=timeout, env=e, cwd=cwd)
    return p.returncode, p.stdout + p.stderr


def report_of(folder):
    path = os.path.join(folder, "report.md")
    return open(path, encoding="utf-8", errors="replace").read() if os.path.exists(path) else ""


def untrusted(name, args, env=None, prefix=()):
    """`geomech check FILE --untrusted`, its exit status and everything it said (its report too)."""
    report = os.path.join(OUT, "report-" + os.path.basename(name))
    shutil.rmtree(report, ignore_errors=True)
    path = name if os.path.isabs(name) else os.path.join(HOSTILE, name)
    rc, text = run(["check", path, "--untrusted", "--report", report, "--cache-dir", os.path.join(OUT, "cache")] + args,
                   env=env, prefix=prefix)
    return rc, text + report_of(report)


def stand_in_bwrap(path, fails_when):
    """A bubblewrap that fails, as a container's or a broken machine's does, when its arguments hold
    `fails_when` (the compile binds its output folder with --bind), and is the real one otherwise."""
    real = shutil.which("bwrap") or "/usr/bin/bwrap"
    with open(path, "w") as f:
        f.write("#!/bin/sh\n"
                "case \" $* \" in\n"
                "  *%s*) echo 'bwrap: Can'\\''t mount tmpfs on /newroot: Operation not permitted' >&2; exit 1 ;;\n"
                "esac\n"
                "exec %s \"$@\"\n" % (fails_when, real))
    os.chmod(path, 0o755)
    return path


def machine_words(text):
    return "grader's machine" in text or "the machine's fault" in text or "GRADER ERROR" in text


shutil.rmtree(OUT, ignore_errors=True)
os.makedirs(OUT)
NARROW = ["--scalar", "double"]

if MODE == "compile":
    rc, text = untrusted("line_bwrap.cpp", NARROW)
    check(rc == 2 and "does not compile" in text,
          "line_bwrap.cpp: a file that does not compile should be 'does not compile' (exit 2), got %d:\n%s"
          % (rc, text[-2500:]))
    check(not machine_words(text), "line_bwrap.cpp: its #line passed its compile error off as the machine's:\n" + text[-2500:])
    # The control: the attack is real, the compiler's output begins as bubblewrap's own error would.
    log = re.search(r"the compiler's full output: (\S+)", text)
    output = open(log.group(1), errors="replace").read().split("\n\n", 1)[-1] if log else ""
    check(output.startswith("bwrap: Can't find source path"),
          "line_bwrap.cpp: the control: the compiler's output should begin with the sandbox's tool's name:\n" + output[:600])
    # A full check compiles the exact piece too: it fails there alone, with the compiler's words.
    rc, text = untrusted("line_bwrap_exact.cpp", ["-p", "definition_vee"])
    check(rc in (0, 1) and "definition_vee" in text,
          "line_bwrap_exact.cpp: the file compiles in double and should be checked (exit 0 or 1), got %d:\n%s"
          % (rc, text[-2500:]))
    check(not machine_words(text),
          "line_bwrap_exact.cpp: its exact piece's #line passed a compile error off as the machine's:\n" + text[-2500:])
    check(re.search(r"definition_vee +[^\n]*PASS[^\n]*NOT PROVIDED", text) is not None,
          "line_bwrap_exact.cpp: vee should pass in double and 50 digits and not be provided in exact:\n" + text[-2500:])
    notes = [os.path.join(d, "build-notes.json") for d in
             (os.path.join(OUT, "cache", e) for e in os.listdir(os.path.join(OUT, "cache")) if e.startswith("line_bwrap_exact"))]
    said = " ".join(open(n).read() for n in notes if os.path.exists(n))
    check("does not compile for exact" in said and "this piece does not compile" in said,
          "line_bwrap_exact.cpp: the exact piece's failure should be the file's, in the compiler's words: " + said[:1500])
    # The control: a bubblewrap that really fails for the compile is the machine's, exit 3.
    fake = stand_in_bwrap(os.path.join(OUT, "bwrap-failing-compiles"), "--bind")
    rc, text = untrusted(os.path.join(SOURCE, "examples", "students", "correct.cpp"), NARROW + ["-p", "definition_vee"],
                         env={"GEOMECH_BWRAP": fake})
    check(rc == 3 and "the sandbox could not start the compiler" in text,
          "a real sandbox failure at the compile should be the machine's (exit 3), got %d:\n%s" % (rc, text[-2500:]))

elif MODE == "herd":
    for name, timeout in (("herd.py", "2"), ("herd.cpp", "2"), ("herd.m", "3")):
        rc, text = untrusted(name, NARROW + ["-p", "definition_euler_3_8", "-p", "definition_vee", "--timeout", timeout,
                                              "--jobs", "1"])
        check(rc == 1, "%s: a herd of its own should end in the code's TIMEOUT (exit 1), got %d:\n%s" % (name, rc, text[-3000:]))
        check(re.search(r"TIMEOUT +definition_euler_3_8", text) is not None,
              "%s: definition_euler_3_8 should be TIMEOUT:\n%s" % (name, text[-3000:]))
        # Its CPU time may run out first (a shell loop whose fork is refused spins): the code's too.
        check("it starves itself" in text or "it waits" in text or "s of CPU time" in text,
              "%s: the TIMEOUT should say, in the kernel's words, that it starves itself, waits or used its CPU "
              "time:\n%s" % (name, text[-3000:]))
        check(not machine_words(text) and "machine starved" not in text,
              "%s: a herd of its own children passed off as a starved machine:\n%s" % (name, text[-3000:]))
        check(re.search(r"definition_vee +[^\n]*PASS", text) is not None,
              "%s: vee, which is correct, should still pass:\n%s" % (name, text[-3000:]))

elif MODE == "limits":
    # Processes of the sandbox's user outside it (as root: nobody's) do not change its count.
    outside = []
    if ROOT:
        for _ in range(10):
            outside.append(subprocess.Popen(["setpriv", "--reuid=65534", "--regid=65534", "--clear-groups", "--",
                                             "sleep", "120"]))
    try:
        rc, text = untrusted("fork_count.py", NARROW + ["-p", "definition_hamiltonian_3_4", "--jobs", "1"])
    finally:
        for p in outside:
            p.kill()
            p.wait()
    m = re.search(r"forked (\d+) children", text)
    check(rc == 1 and m is not None, "fork_count.py: the check should FAIL with how many it forked (exit 1), got %d:\n%s"
          % (rc, text[-2500:]))
    if m:
        n = int(m.group(1))
        # 32 tasks in the sandbox: the process that runs the slot among them.
        check(n + 1 <= 32, "fork_count.py: forked %d children, past the documented 32 tasks of a sandbox" % n)
        check(n >= 20, "fork_count.py: the control: forked only %d children; processes outside the sandbox should not "
                       "count against it" % n)
        print("fork_count.py: %d children forked, then refused (%d processes of the sandbox's user outside it)"
              % (n, len(outside)))
    check(not machine_words(text), "fork_count.py: forks past the limit passed off as the machine's:\n" + text[-2500:])
    # The controls, in-process (no sandbox): the attacks work there.
    rc, text = run(["check", os.path.join(HOSTILE, "fork_count.py"), "-p", "definition_hamiltonian_3_4", "--scalar",
                    "double", "--jobs", "1"])
    m = re.search(r"forked (\d+) children", text)
    check(m is not None and int(m.group(1)) > 32,
          "fork_count.py: the control: in-process it should fork more than 32 children:\n" + text[-1500:])
    rc, text = run(["check", os.path.join(HOSTILE, "memory_total.py"), "-p", "definition_casimir", "--scalar", "double",
                    "--jobs", "1", "--memory-limit", "600"])
    check("3 children held 200 MiB" in text,
          "memory_total.py: the control: in-process its three children should hold 600 MiB at once:\n" + text[-1500:])
    rc, text = run(["self-test", "--no-python"])
    total = "MiB in all (its cgroup)" in text
    print("self-test: " + " ".join(l for l in text.splitlines() if "limits" in l))
    rc, text = untrusted("memory_total.py", NARROW + ["-p", "definition_casimir", "--memory-limit", "600", "--jobs", "1"])
    check(rc == 1, "memory_total.py: memory past the total should be the code's (exit 1), got %d:\n%s" % (rc, text[-2500:]))
    check(not machine_words(text), "memory_total.py: memory past the total passed off as the machine's:\n" + text[-2500:])
    m = re.search(r"(\d+) children held 200 MiB each at once", text)
    if total:
        check(m is None or int(m.group(1)) <= 2,
              "memory_total.py: the sandbox's processes held more than its 600 MiB total:\n" + text[-2500:])
        print("memory_total.py: " + (m.group(0) if m else "the kernel killed what went past the total"))
    else:
        print("memory_total.py: no cgroup keeps a memory total here (not root): each process has its own writable-memory "
              "limit, " + (m.group(0) if m else "nothing held"))

elif MODE == "starved":
    slow = os.path.join(SOURCE, "tests", "blame", "slow_hat.py")
    args = NARROW + ["-p", "hat_is_cross_product", "--timeout", "4", "--jobs", "1", "--cases", "150", "--case-budget", "0"]
    rc, text = untrusted(slow, args)
    check(rc == 0 and re.search(r"hat_is_cross_product +[^\n]*PASS", text) is not None,
          "slow_hat.py: the control, alone, should PASS (exit 0), got %d:\n%s" % (rc, text[-2500:]))
    # Sixteen busy processes outside the sandbox, on the first core, the check pinned there too: it
    # gets about a seventeenth of the core, and its wall clock passes the busy limit (6 s here) long
    # before its 1.5 s of CPU are done.
    burn = "import os\nos.sched_setaffinity(0, {%d})\nwhile True: pass\n"
    cores = sorted(os.sched_getaffinity(0))
    # Each in a session of its own: the kernel's autogroup gives each its own share, as sixteen
    # users' programs have (in one session they would share one share).
    burners = [subprocess.Popen([sys.executable, "-c", burn % cores[0]], start_new_session=True) for _ in range(16)]
    try:
        time.sleep(0.5)
        rc, text = untrusted(slow, args, env={"GEOMECH_TEST_LIMITS": "1 0 1.5"}, prefix=["taskset", "-c", str(cores[0])])
    finally:
        for p in burners:
            p.kill()
            p.wait()
    check(rc == 3, "slow_hat.py starved: a machine's ERROR should exit 3, got %d:\n%s" % (rc, text[-2500:]))
    check("the machine starved it" in text, "slow_hat.py starved: the ERROR should say the machine starved it:\n" + text[-2500:])
    check(re.search(r"hat_is_cross_product +[^\n]*(FAIL|TIMEOUT)", text) is None,
          "slow_hat.py starved: a starved honest check was graded:\n" + text[-2500:])

elif MODE == "class":
    klass = os.path.join(OUT, "class")
    os.makedirs(klass)
    shutil.copy(os.path.join(SOURCE, "examples", "class", "submissions", "alice.py"), klass)
    with open(os.path.join(klass, "zoe.cpp"), "w") as f:  # the hat map and vee, right
        f.write("#include <geomech/student.hpp>\nusing namespace gm;\nstruct Zoe {\n"
                "  template <class T> static Mat3<T> hat(const Vec3<T>& v) {\n"
                "    Mat3<T> m;\n    m << T(0), -v(2), v(1), v(2), T(0), -v(0), -v(1), v(0), T(0);\n    return m;\n  }\n"
                "  template <class T> static Vec3<T> vee(const Mat3<T>& m) { return Vec3<T>(m(2, 1), m(0, 2), m(1, 0)); }\n"
                "};\nGEOMECH_STUDENT(Zoe);\n")
    fake = stand_in_bwrap(os.path.join(OUT, "bwrap-failing-for-zoe"), "zoe-")
    env = {"GEOMECH_BWRAP": fake, "GEOMECH_PYTHON": "/usr/bin/python3"}
    report = os.path.join(OUT, "report")
    grades = os.path.join(OUT, "grades.csv")
    base = ["check-class", klass, "--report", report, "--grades", grades, "--cache-dir", os.path.join(OUT, "cache"),
            "--scalar", "double", "-p", "definition_hat", "-p", "definition_vee"]

    def zoe_row():
        rows = list(csv.reader(open(grades, encoding="utf-8"))) if os.path.exists(grades) else []
        return ([r for r in rows if r and r[0] == "zoe"] or [None])[0], rows

    for attempt in (1, 2, 3):
        rc, text = run(base, env=env)
        summary = open(os.path.join(report, "summary.md"), encoding="utf-8").read() if os.path.exists(
            os.path.join(report, "summary.md")) else ""
        check(rc == 3, "class run %d: a GRADER ERROR should exit 3, got %d:\n%s" % (attempt, rc, text[-2500:]))
        line = [l for l in summary.splitlines() if l.startswith("| zoe ")]
        check(line and "GRADER ERROR" in line[0] and "0.00" not in line[0] and "| - |" in line[0],
              "class run %d: zoe's summary row should show GRADER ERROR and no grade: %r" % (attempt, line))
        console = [l for l in text.splitlines() if l.startswith("zoe ") and "GRADER ERROR" in l]
        check(console and "0.00" not in console[0], "class run %d: the console should show no grade for zoe: %r"
              % (attempt, console))
        zoe, rows = zoe_row()
        check(zoe is not None and zoe[4] == "", "class run %d: the gradebook should leave zoe's grade empty: %r" % (attempt, rows))
        alice = [r for r in rows if r and r[0] == "alice"]
        check(alice and alice[0][4] != "", "class run %d: alice, checked fine, should have a grade: %r" % (attempt, rows))
        row = json.load(open(os.path.join(report, "zoe", "class-row.json")))["row"]
        if attempt == 1:
            check(not row.get("suspect"), "class run 1: a first machine fault is checked again, not suspect yet")
        elif attempt == 2:
            check(row.get("suspect") and len(row.get("earlier_faults", [])) == 1,
                  "class run 2: the same fault again, classmates fine: suspect, with the first run's evidence: %r" % row)
            check("suspect" in summary and "the lecturer decides" in summary,
                  "class run 2: summary.md should report zoe to the lecturer as suspect:\n" + summary[-2500:])
        else:
            check("kept for the lecturer to decide" in text and "compiling" not in text.split("zoe")[0][-200:],
                  "class run 3: a suspect row should be kept, not checked again at every run:\n" + text[-2500:])
    rc, text = run(base + ["--regrade", "zoe"], env={"GEOMECH_PYTHON": "/usr/bin/python3"})
    check(rc in (0, 1), "--regrade zoe on a working machine should check and grade her (exit %d):\n%s" % (rc, text[-2500:]))
    zoe, rows = zoe_row()
    check(zoe is not None and zoe[4] == "100.00", "--regrade zoe: she should have her grade now: %r\n%s" % (rows, text[-2000:]))

else:
    sys.exit("unknown mode " + MODE)

if failures:
    print("\n".join("FAILED: " + f for f in failures))
    sys.exit(1)
print(MODE + ": every attack charged to the code, every fault of the machine its own")
