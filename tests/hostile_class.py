"""A class folder as a hostile student makes it, checked by `geomech check-class`.

    python3 hostile_class.py GEOMECH SOURCE_DIR OUT_DIR MODE

MODE is `root` (the harness runs as it is started: root in CI, as a lecturer's CI runs it) or
`user` (started as root, the class is checked as the ordinary user nobody; started as anyone
else, as that user). The class is built here, in OUT_DIR, since archives restore what a source
tree should not hold (symbolic links, FIFOs, sockets, hard links):

  honest.py     an honest student: hat and the Hamiltonian (3.4), right
  leak.py       a symbolic link to a root-only token (a 0600 file in a 0700 folder)
  copycat/      copycat.py, a symbolic link to ../honest.py (would earn honest's grade)
  headers/      headers.cpp including evil.hpp (-> /etc/shadow) and token.hpp (-> the token)
  fifo.py       a FIFO (the fingerprint read it and hung the class)
  piped/        piped.py and a FIFO beside it
  zero.py       a symbolic link to /dev/zero (would read without end)
  sock/         sock.py and a UNIX socket beside it
  hard.py       a hard link to the token (root only: only root can link a file it cannot read)
  flood.py      hat raises a 20 MiB message
  forge.py      raises at import a message that closes the summary's fence and forges a row,
                raw HTML and terminal escapes
  alice/        an honest C++ student (alice.cpp and alice.hpp), her header also in the flat folder
  mallory.cpp   includes "alice.hpp" to copy alice's work (and its compile error would quote it)
  stdin.cpp     #include "/dev/stdin" (the compiler read the lecturer's terminal)
  ...py         implementation name '..' (wrote into the report folder's parent)
  =1+1.py       a spreadsheet formula as a name
  -rf.py, a name with a newline and one with an escape sequence

Each attack's defended outcome is asserted, and the honest students' rows and grades are those of
a class holding only them (checked first). Exit status 0 when all holds; otherwise the first
failed assertion, with what was seen.
"""
import csv
import json
import os
import re
import shutil
import socket
import stat
import subprocess
import sys
import time

GEOMECH, SOURCE, OUT, MODE = sys.argv[1:5]
CANARY = "moodle_token: GEOMECH-CANARY-46-" + str(os.getpid())
TYPED = "TYPED-AT-THE-TERMINAL-46"
ALICE_PRIVATE = "ALICE-PRIVATE-LINE-46"
ROOT = os.geteuid() == 0
AS_USER = MODE == "user" and ROOT
OPTIONS = ["--scalar", "double", "-p", "hat_is_cross_product", "-p", "definition_hamiltonian_3_4",
           "-p", "definition_hat", "--parallel", "2", "--timeout", "60"]
RUBRIC = {"assignment": ["hat", "hamiltonian_3_4"]}

failures = []


def fail(what, seen=""):
    failures.append(what + ("\n--- seen:\n" + seen[:4000] if seen else ""))


def write(path, text, mode=0o644):
    with open(path, "w") as f:
        f.write(text)
    os.chmod(path, mode)


HONEST_PY = '''
def hat(v):
    return [[0 * v[0], -v[2], v[1]], [v[2], 0 * v[0], -v[0]], [-v[1], v[0], 0 * v[0]]]


def hamiltonian_3_4(I, P):
    return (P[0] * P[0] / I[0] + P[1] * P[1] / I[1] + P[2] * P[2] / I[2]) / 2
'''

FLOOD_PY = HONEST_PY.replace("def hat(v):\n", "def hat(v):\n    raise ValueError('x' * (20 << 20))\n")

FORGE_TEXT = ("```\n\n| alice | **FORGED PASS** | 9/9 |\n\n# FORGED HEADING\n"
              "<img src=x onerror=alert(1)>\n\x1b]0;pwned\x07\x1b[2J\x1b[32mPASS\x1b[0m\n````````\n")
FORGE_PY = "raise RuntimeError(" + repr(FORGE_TEXT) + ")\n"

ALICE_HPP = '''// ''' + ALICE_PRIVATE + '''
#pragma once
#include <geomech/student.hpp>
template <class T>
gm::Mat3<T> alice_hat(const gm::Vec3<T>& v) {
  gm::Mat3<T> m;
  m << T(0), -v(2), v(1), v(2), T(0), -v(0), -v(1), v(0), T(0);
  return m;
}
'''
ALICE_CPP = '''#include "alice.hpp"
struct Alice {
  template <class T>
  static gm::Mat3<T> hat(const gm::Vec3<T>& v) { return alice_hat(v); }
};
GEOMECH_STUDENT(Alice);
'''
MALLORY_CPP = '''#include "alice.hpp"
struct Mallory {
  template <class T>
  static gm::Mat3<T> hat(const gm::Vec3<T>& v) { return alice_hat(v); }
};
GEOMECH_STUDENT(Mallory);
'''
STDIN_CPP = '''#include <geomech/student.hpp>
#include "/dev/stdin"
struct Stdin {
  template <class T>
  static gm::Mat3<T> hat(const gm::Vec3<T>& v) {
    gm::Mat3<T> m;
    m << T(0), -v(2), v(1), v(2), T(0), -v(0), -v(1), v(0), T(0);
    return m;
  }
};
GEOMECH_STUDENT(Stdin);
'''
HEADERS_CPP = '#include <geomech/student.hpp>\n#include "evil.hpp"\n#include "token.hpp"\nstruct H {};\nGEOMECH_STUDENT(H);\n'


def make_class(folder, secret, honest_only):
    os.makedirs(folder)
    os.chmod(folder, 0o755)
    write(os.path.join(folder, "honest.py"), HONEST_PY)
    # Alice hands in a folder (her file and her header), and her header sits in the flat folder
    # too, where the old harness copied it into every C++ compile.
    os.makedirs(os.path.join(folder, "alice"))
    write(os.path.join(folder, "alice", "alice.cpp"), ALICE_CPP)
    write(os.path.join(folder, "alice", "alice.hpp"), ALICE_HPP)
    write(os.path.join(folder, "alice.hpp"), ALICE_HPP)
    if honest_only:
        return
    token = os.path.join(secret, "token")
    os.symlink(token, os.path.join(folder, "leak.py"))
    os.makedirs(os.path.join(folder, "copycat"))
    os.symlink("../honest.py", os.path.join(folder, "copycat", "copycat.py"))
    os.makedirs(os.path.join(folder, "headers"))
    write(os.path.join(folder, "headers", "headers.cpp"), HEADERS_CPP)
    os.symlink("/etc/shadow", os.path.join(folder, "headers", "evil.hpp"))
    os.symlink(token, os.path.join(folder, "headers", "token.hpp"))
    os.mkfifo(os.path.join(folder, "fifo.py"))
    os.makedirs(os.path.join(folder, "piped"))
    write(os.path.join(folder, "piped", "piped.py"), HONEST_PY)
    os.mkfifo(os.path.join(folder, "piped", "pipe"))
    os.symlink("/dev/zero", os.path.join(folder, "zero.py"))
    os.makedirs(os.path.join(folder, "sock"))
    write(os.path.join(folder, "sock", "sock.py"), HONEST_PY)
    s = socket.socket(socket.AF_UNIX)
    s.bind(os.path.join(folder, "sock", "socket"))
    s.close()
    if ROOT:
        os.link(token, os.path.join(folder, "hard.py"))
    write(os.path.join(folder, "flood.py"), FLOOD_PY)
    write(os.path.join(folder, "forge.py"), FORGE_PY)
    write(os.path.join(folder, "mallory.cpp"), MALLORY_CPP)
    write(os.path.join(folder, "stdin.cpp"), STDIN_CPP)
    write(os.path.join(folder, "...py"), HONEST_PY)
    write(os.path.join(folder, "=1+1.py"), HONEST_PY)
    write(os.path.join(folder, "-rf.py"), HONEST_PY)
    write(os.path.join(folder, "new\nline.py"), HONEST_PY)
    write(os.path.join(folder, "esc\x1b[31m.py"), HONEST_PY)


def run_class(folder, reports, cache, grades):
    rubric = os.path.join(OUT, "rubric.json")
    write(rubric, json.dumps(RUBRIC))
    cmd = [GEOMECH, "check-class", folder, "--report", reports, "--cache-dir", cache, "--grades", grades,
           "--rubric", rubric, "--fresh"] + OPTIONS
    os.makedirs(os.path.dirname(grades), exist_ok=True)
    if AS_USER:  # what the user writes is theirs; the class stays root's
        for d in (reports, cache, os.path.dirname(grades)):
            os.makedirs(d, exist_ok=True)
            os.chown(d, 65534, 65534)
        cmd = ["setpriv", "--reuid=65534", "--regid=65534", "--clear-groups", "--"] + cmd
    start = time.time()
    # What is typed at the lecturer's terminal: the class run's input.
    p = subprocess.run(cmd, input=TYPED + "\n", capture_output=True, text=True, errors="replace", timeout=1500)
    return p.returncode, p.stdout + p.stderr, time.time() - start


def files_under(d):
    for root, dirs, files in os.walk(d):
        for f in files:
            yield os.path.join(root, f)


def text_outside_fences(md):
    """The lines of a Markdown file that are not inside a fenced code block (a fence of n backticks
    is closed only by a line of at least n backticks)."""
    out, fence = [], 0
    for line in md.split("\n"):
        m = re.match(r"^(`{3,})", line)
        if fence == 0 and m:
            fence = len(m.group(1))
            continue
        if fence and m and len(m.group(1)) >= fence and line.strip("`") == "":
            fence = 0
            continue
        if not fence:
            out.append(line)
    return out


def grade_rows(grades):
    with open(grades, newline="", encoding="utf-8") as f:
        return {r[0]: r for r in csv.reader(f)}


def summary_rows(summary):
    rows = {}
    for line in text_outside_fences(summary):
        if line.startswith("| ") and not line.startswith("| implementation"):
            cells = [c.strip() for c in re.split(r"(?<!\\)\|", line)[1:-1]]
            rows[cells[0]] = cells
    return rows


def main():
    if os.path.exists(OUT):
        shutil.rmtree(OUT)
    os.makedirs(OUT)
    os.chmod(OUT, 0o755)
    secret = os.path.join(OUT, "secret")
    os.makedirs(secret)
    write(os.path.join(secret, "token"), CANARY + "\n", 0o600)
    os.chmod(secret, 0o700)

    # The honest students alone: what the hostile class must not change.
    base = os.path.join(OUT, "base")
    make_class(os.path.join(base, "class"), secret, True)
    rc, out, secs = run_class(os.path.join(base, "class"), os.path.join(base, "reports"), os.path.join(base, "cache"),
                              os.path.join(base, "book", "grades.csv"))
    if rc not in (0, 1):
        fail("the honest class did not run (exit %d)" % rc, out)
        return
    base_summary = open(os.path.join(base, "reports", "summary.md"), encoding="utf-8").read()
    base_rows, base_grades = summary_rows(base_summary), grade_rows(os.path.join(base, "book", "grades.csv"))
    # alice writes hat only, of the rubric's two slots: INCOMPLETE, every check of hers passing
    # (the assignment decides a PASS).
    for name, result in (("honest", "PASS"), ("alice", "**INCOMPLETE**")):
        if base_rows.get(name, [None, None])[1] != result:
            fail("the honest class: %s is not %s" % (name, result), base_summary)

    klass = os.path.join(OUT, "class")
    make_class(klass, secret, False)
    # Control: the class is as hostile as it says: followed naively (as the harness used to), the
    # links reach the token and a classmate's file, and the FIFOs and the socket are what they are.
    if ROOT:
        if open(os.path.join(klass, "leak.py")).read().strip() != CANARY:
            fail("control: leak.py does not reach the token")
        if open(os.path.join(klass, "hard.py")).read().strip() != CANARY:
            fail("control: hard.py is not the token")
    if open(os.path.join(klass, "copycat", "copycat.py")).read() != HONEST_PY:
        fail("control: copycat.py does not reach honest.py")
    for f, test in (("fifo.py", stat.S_ISFIFO), ("piped/pipe", stat.S_ISFIFO), ("sock/socket", stat.S_ISSOCK)):
        if not test(os.lstat(os.path.join(klass, f)).st_mode):
            fail("control: %s is not what the attack needs" % f)
    reports = os.path.join(OUT, "reports")
    grades = os.path.join(OUT, "book", "grades.csv")
    cache = os.path.join(OUT, "cache")
    rc, console, secs = run_class(klass, reports, cache, grades)
    print("hostile class (%s%s): exit %d in %.1f s" % (MODE, ", as nobody" if AS_USER else "", rc, secs))
    if rc not in (0, 1):
        fail("the hostile class did not finish with a verdict (exit %d)" % rc, console)
        return
    summary = open(os.path.join(reports, "summary.md"), encoding="utf-8", errors="replace").read()
    rows = summary_rows(summary)
    book = grade_rows(grades)

    # The honest students: the same row and grade as alone.
    for name in ("honest", "alice"):
        if rows.get(name) != base_rows.get(name):
            fail("%s's row changed beside the hostile class: %s against %s" % (name, rows.get(name), base_rows.get(name)))
        if book.get(name) != base_grades.get(name):
            fail("%s's grade changed beside the hostile class: %s against %s" % (name, book.get(name), base_grades.get(name)))

    # Nothing of the secret anywhere: reports, gradebook, console, the compiler's cache.
    for where in list(files_under(reports)) + list(files_under(cache)) + [grades]:
        try:
            data = open(where, "rb").read()
        except OSError:
            continue
        if CANARY.encode() in data:
            fail("the root-only token was copied into " + where)
        if TYPED.encode() in data:
            fail("what was typed at the terminal reached " + where)
        if ALICE_PRIVATE.encode() in data and "/alice/" not in where and "/alice-" not in where:
            fail("alice's header reached " + where)  # a report, or another student's compile
    for text, what in ((console, "the console"),):
        if CANARY in text or TYPED in text:
            fail("a secret reached " + what, text)
    if ROOT and not AS_USER:
        shadow = open("/etc/shadow", "rb").read()
        for where in files_under(cache):
            if open(where, "rb").read() == shadow:
                fail("a copy of /etc/shadow is in the cache: " + where)

    # Each attack refused or defended, naming the file.
    expect = {
        "leak": r"NOT CHECKED",
        "copycat": r"NOT CHECKED",
        "headers": r"NOT CHECKED",
        "fifo": r"NOT CHECKED",
        "piped": r"NOT CHECKED",
        "zero": r"NOT CHECKED",
        "sock": r"NOT CHECKED",
        "forge": r"NOT CHECKED",
        "mallory": r"DOES NOT COMPILE",
        "stdin": r"INCOMPLETE",  # it compiles (reading nothing) and its hat passes; hat is one slot of two
        "flood": r"FAIL",
    }
    if ROOT and not AS_USER:
        expect["hard"] = r"NOT CHECKED"
    words = summary
    for name, outcome in expect.items():
        row = rows.get(name)
        if not row or not re.search(outcome, row[1]):
            fail("%s: expected %s in the summary, got %s" % (name, outcome, row), summary)
    reasons = {
        "leak": r"leak\.py: a symbolic link",
        "copycat": r"copycat/copycat\.py: a symbolic link",
        "headers": r"headers/evil\.hpp: a symbolic link",
        "fifo": r"fifo\.py: a FIFO",
        "piped": r"piped/pipe: a FIFO",
        "zero": r"zero\.py: a symbolic link",
        "sock": r"sock/socket: a socket",
        "mallory": r"alice\.hpp: No such file",
        "dotdot": r"cannot be checked under the name '\.\.'",
        "dash": r"'-rf\.py' cannot be checked under the name '-rf'",
        "newline": r"control character",
    }
    if ROOT and not AS_USER:
        reasons["hard"] = r"hard\.py: a file with 2 names"
    for what, pattern in reasons.items():
        if not re.search(pattern, words):
            fail("the summary does not say why for %s ('%s')" % (what, pattern), summary)

    # Names: nothing written above the report folder; formulas made text in the gradebook.
    for stray in ("class-row.json", "report.md", "verdicts.json"):
        if os.path.exists(os.path.join(OUT, stray)):
            fail("a report file was written outside the report folder: " + os.path.join(OUT, stray))
    formula = [r for r in book.values() if "1+1" in r[0]]
    if not formula or formula[0][0] != "'=1+1":
        fail("the gradebook cell of =1+1.py is not made text: %s" % formula)
    for row in book.values():
        for cell in row:
            if cell[:1] in ("=", "+", "@", "\t", "\r") or (cell[:1] == "-" and not re.match(r"^-?\d+(\.\d+)?$", cell)):
                fail("a gradebook cell starts like a formula: %r" % cell)

    # Inert: no raw escape anywhere a lecturer looks; the forgery only inside a code block.
    for where in list(files_under(reports)) + [grades]:
        if where.endswith((".md", ".json", ".xml", ".csv")):
            data = open(where, "rb").read()
            if b"\x1b" in data or b"\x07" in data:
                fail("a raw escape character in " + where)
    if "\x1b" in console or "\x07" in console:
        fail("a raw escape character on the console", repr(console[-3000:]))
    outside = "\n".join(text_outside_fences(summary))
    for forged in ("FORGED PASS", "# FORGED HEADING", "<img"):
        if forged in outside:
            fail("the forged text '%s' is live in summary.md (outside a code block)" % forged, summary)
    if "FORGED PASS" not in summary:
        fail("the forging submission's message is not shown at all (it should be, as inert text)", summary)

    # Floods: bounded reports, the cut said.
    flood_dir = os.path.join(reports, "flood")
    total = sum(os.path.getsize(f) for f in files_under(flood_dir)) if os.path.isdir(flood_dir) else 0
    if total == 0 or total > 4 << 20:
        fail("the flooding student's report folder holds %d bytes (expected a report, under 4 MiB)" % total)
    report_md = os.path.join(flood_dir, "report.md")
    if os.path.exists(report_md) and "bytes cut" not in open(report_md, encoding="utf-8", errors="replace").read():
        fail("the flooding student's report does not say its message was cut")


main()
if failures:
    print("\n\n".join("FAILED: " + f for f in failures))
    sys.exit(1)
print("every attack defended; the honest students' rows and grades are those of the honest class alone")
