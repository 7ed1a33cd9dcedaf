#!/usr/bin/env python3
"""docs/ENGINES.md's ledger: every real engine the suite has checked, each step's claims with where
the engine's documentation makes them, the verdict, what was measured, the cause, and the test that
confirms each finding with the engine called directly.

The engines are listed in examples/engines/ledger.json; their verdicts are read from the reports
the trusted ctest of each writes (BUILD/tests/engine-reports/*/report/verdicts.json), their versions
from pkg-config and npm on this machine. `./geomech ledger` runs those tests, then this with
--write; ctest docs.engine_ledger_current runs this with --check after the same tests, so a verdict
that changes without the ledger fails there, naming the command that regenerates it.

    engine_ledger.py PROJECT_DIR BUILD_DIR (--write | --check) [FILE]   (FILE: docs/ENGINES.md)
    engine_ledger.py PROJECT_DIR BUILD_DIR --tests     the ctest names whose reports it reads, as a -R regex
"""
import json
import os
import re
import subprocess
import sys
import tempfile

BEGIN = "<!-- ledger: written by ./geomech ledger from the engines' reports; edit examples/engines/ledger.json, not this -->"
END = "<!-- ledger end -->"


def version(v, project):
    if "pkg-config" in v:
        try:
            r = subprocess.run(["pkg-config", "--modversion", v["pkg-config"]], capture_output=True, text=True)
        except OSError:
            return "unknown (pkg-config is not installed)"
        return ("Debian's %s %s" % (v["pkg-config"], r.stdout.strip())) if r.returncode == 0 else "not installed"
    if "npm" in v:
        path = os.path.join(project, v["folder"], "node_modules", v["npm"], "package.json")
        try:
            with open(path) as f:
                return "npm %s %s" % (v["npm"], json.load(f)["version"])
        except (OSError, ValueError, KeyError):
            return "npm %s, not installed" % v["npm"]
    return "unknown"


def cell(text):
    return " ".join(str(text).split()).replace("|", "\\|")


def cause_of(claim, integrator, messages):
    """What the check that decided a failing claim says of it, in the words of its first line: for a
    step whose own equation differs from the notes', the clause that names the difference ("the
    gyroscopic term (I Omega) x Omega is missing", read by the check at the failing input); when the
    check found the equation right and named no cause, "cause not identified" with the measurement;
    else the line itself."""
    why = claim["why"]  # "integrator_order [double]", the check that decided it
    if " [" not in why:
        return ""
    prop, scalar = why.split(" [", 1)
    message = messages.get((integrator, prop.strip(), scalar.split("]", 1)[0]), "")
    lines = message.split("\n")
    first = lines[0]
    if first.startswith("the step's own equation:"):
        if "the equation is not the cause" in first and len(lines) > 1:  # then the measurement is the finding
            return ("cause not identified (its field follows the notes'; the evidence: " +
                    re.sub(r"^false claim '[^']*': [^:]*: ", "", lines[1]) + ")")
        return brief(first.split("; in the notes'", 1)[0].split(": ")[-1])
    return brief(first_clause(first))[:300]


def first_clause(text):
    """The text up to its first "; " outside brackets."""
    depth = 0
    for k, ch in enumerate(text):
        depth += ch in "([" and 1 or (-1 if ch in ")]" else 0)
        if depth == 0 and text.startswith("; ", k):
            return text[:k]
    return text


def brief(text):
    return re.sub(r"\[[-0-9.e+, ]+\]", "[...]", text)  # a vector at the failing input: the report has it


def engine_section(e, project, build):
    path = os.path.join(build, e["report"])
    head = "### %s (%s, built in %s)\n\n" % (e["engine"], version(e["version"], project), e["built"])
    head += "Wrapper `%s`; verdicts from ctest `%s`; each finding confirmed by `%s`.\n" % (
        e["wrapper"], e["ctest"], e["confirmed_by"])
    if e.get("claims_nothing"):
        head += "Nothing is claimed: %s; the suite characterises.\n" % e["claims_nothing"]
    try:
        with open(path) as f:
            report = json.load(f)
    except (OSError, ValueError) as err:
        return head + "\n**No report**: %s (%s). Run `./geomech ledger`.\n" % (path, err), False
    rows = ["| step | claim | claimed, where documented | verdict | measured | cause |", "|---|---|---|---|---|---|"]
    messages = {(v["integrator"], v["property"], v["scalar"]): v["message"] for v in report["verdicts"]}
    for i in report["integrators"]:
        for c in i["claims"]:
            if c["status"] in ("", "-"):  # not measured by the checks this run selected
                continue
            where = e["documented"].get("%s %s" % (i["name"], c["claim"]))
            claimed = c["claimed"] if c["claimed"] not in ("", "no") else "not claimed"
            if where:
                claimed += ": " + where
            status = "**%s**" % c["status"] if c["fails"] else c["status"]
            cause = cause_of(c, i["name"], messages) if c["fails"] else ""
            rows.append("| `%s` | %s | %s | %s | %s | %s |" % (
                i["name"], cell(c["claim"]), cell(claimed), cell(status), cell(c["measured"]), cell(cause)))
    run = report.get("selection") or "every property"
    head += "Run: %s.\n\n" % cell(run)
    return head + "\n".join(rows) + "\n", True


def ledger(project, build):
    with open(os.path.join(project, "examples", "engines", "ledger.json")) as f:
        manifest = json.load(f)
    out = [BEGIN, "", "## The ledger", "",
           "Every real engine the suite has checked, regenerated by `./geomech ledger` (it runs each engine's "
           "trusted check under ctest, then writes this section from their reports). A claim is the "
           "wrapper's, stated from where the engine's documentation makes it; a row not claimed is the "
           "suite's characterisation. No other published audit of real engines' free rigid body is known "
           "to us.", ""]
    complete = True
    for e in manifest["engines"]:
        text, ok = engine_section(e, project, build)
        complete &= ok
        out += [text]
    out += [END]
    return "\n".join(out) + "\n", complete


def splice(doc, section):
    if BEGIN in doc and END in doc:
        a, b = doc.index(BEGIN), doc.index(END) + len(END) + 1
        return doc[:a] + section + doc[b:]
    return doc.rstrip("\n") + "\n\n" + section


def main(argv):
    if len(argv) < 4 or argv[3] not in ("--write", "--check", "--tests"):
        sys.stderr.write(__doc__)
        return 2
    project, build, mode = argv[1], argv[2], argv[3]
    if mode == "--tests":
        with open(os.path.join(project, "examples", "engines", "ledger.json")) as f:
            names = [e["ctest"].replace(".", "\\.") for e in json.load(f)["engines"]]
        print("^(%s)$" % "|".join(names))
        return 0
    target = argv[4] if len(argv) > 4 else os.path.join(project, "docs", "ENGINES.md")
    section, complete = ledger(project, build)
    with open(target) as f:
        doc = f.read()
    new = splice(doc, section)
    if mode == "--check":
        if new == doc:
            print("the ledger of %s is current" % target)
            return 0
        old = doc[doc.index(BEGIN):doc.index(END)] if BEGIN in doc and END in doc else ""
        a, b = old.splitlines(), section.splitlines()
        for k in range(max(len(a), len(b))):
            if k >= len(a) or k >= len(b) or a[k] != b[k]:
                print("first difference, line %d of the ledger:\n  in %s: %s\n  from the reports: %s" % (
                    k + 1, target, a[k] if k < len(a) else "(nothing)", b[k] if k < len(b) else "(nothing)"))
                break
        print("the ledger of %s is not the engines' verdicts: regenerate it with ./geomech ledger" % target)
        return 1
    if not complete:
        print("a report is missing (above): the ledger is not written")
        return 1
    fd, tmp = tempfile.mkstemp(dir=os.path.dirname(os.path.abspath(target)), prefix=".ledger-")
    with os.fdopen(fd, "w") as f:
        f.write(new)
    os.chmod(tmp, 0o644)
    os.replace(tmp, target)  # never half-written
    print("wrote the ledger of %s" % target)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
