#!/usr/bin/env python3
"""Jupyter notebooks as submissions, end to end, each case read back with nbformat (the notebook
format's own library, Debian's python3-nbformat), not with the suite's reader:

    notebooks.py GEOMECH EXAMPLES OUT CASE [ARGS...]

  first_fix NOTEBOOK CORRECT SLOT [CHECK OPTIONS]
      `geomech check NOTEBOOK` fails, and its first fix names SLOT in a cell and a line: that cell
      (counted from 1, every cell, as nbformat lists them) is a code cell whose saved execution
      count is the one named, whose line defines SLOT, and it is the one cell where NOTEBOOK differs
      from CORRECT (the one mistake). The report and verdicts.json name the same place; an error's
      traceback, when there is one, names cells only.
  correct NOTEBOOK [CHECK OPTIONS]
      the check passes, and the report's "Notebook:" line names what nbformat finds set aside: the
      Markdown cells, the skip-execution cell, the cell magic and the shell escape, by number.
  cell_fails
      notebooks whose third cell fails when run, in each kernel, by raising and by a syntax error:
      exit 2, the message names that cell (with its execution count) and the line in it, as
      nbformat numbers them.
  malformed
      notebooks broken one way each (not JSON, nbformat 3, no cells, a source that is a number, a
      cell without a type, an execution count that is text, no kernel, a kernel of no language the
      suite reads): each exits 2 with a message naming what is wrong, and each the format's own
      validator rejects too (but the kernels, which nbformat leaves free).
  class CLASS_PY [CHECK OPTIONS]
      `geomech check-class` (sandboxed) of a folder holding a Python notebook, a student's folder
      with an Octave notebook in it, a notebook that is not JSON and a .py file (CLASS_PY): one row
      each, the notebooks graded as notebooks, the broken one not checked with what is wrong in it
      and nothing else of the class lost; the summary and the student's feedback page name the cell
      of the first fix, the cell nbformat finds defining it.
Exit 0 when the case holds; otherwise what failed.
"""
import json
import os
import re
import shutil
import subprocess
import sys

import nbformat

PLACE = re.compile(r"\(cell (\d+)(?:, In \[(\d+)\])?, line (\d+)\)")


def fail(what):
    sys.exit("notebooks.py: " + what)


def check(geomech, notebook, out, options):
    shutil.rmtree(out, ignore_errors=True)
    return subprocess.run([geomech, "check", notebook, "--quiet", "--report", out] + options,
                          capture_output=True, text=True)


def defines(source_line, slot):
    return re.search(r"\bdef\s+" + slot + r"\s*\(", source_line) or \
        re.search(r"^\s*function\b.*\b" + slot + r"\s*\(", source_line)


def first_fix(geomech, out, notebook, correct, slot, options):
    r = check(geomech, notebook, out, options)
    if r.returncode != 1:
        fail("%s: exit %d, expected 1 (a mistake)\n%s" % (notebook, r.returncode, r.stderr))
    verdicts = json.load(open(os.path.join(out, "verdicts.json")))
    lines = [f["line"] for f in verdicts.get("first_fix", [])]
    if not lines or ("'%s'" % slot) not in lines[0]:
        fail("the first fix is not %s: %s" % (slot, lines))
    m = PLACE.search(lines[0])
    if not m:
        fail("the first fix names no cell and line: " + lines[0])
    number, count, line = int(m.group(1)), m.group(2), int(m.group(3))
    nb = nbformat.read(notebook, as_version=4)
    ok = nbformat.read(correct, as_version=4)
    if not 1 <= number <= len(nb.cells):
        fail("cell %d: the notebook has %d cells" % (number, len(nb.cells)))
    cell = nb.cells[number - 1]
    if cell.cell_type != "code":
        fail("cell %d is a %s cell" % (number, cell.cell_type))
    if (str(cell.execution_count) if cell.execution_count is not None else None) != count:
        fail("cell %d: its execution count is %s, the first fix says In [%s]" % (number, cell.execution_count, count))
    source = cell.source.split("\n")
    if not 1 <= line <= len(source) or not defines(source[line - 1], slot):
        fail("line %d of cell %d does not define %s: %r" % (line, number, slot, source[line - 1:line]))
    differ = [i + 1 for i, (a, b) in enumerate(zip(nb.cells, ok.cells)) if a.source != b.source]
    if differ != [number]:
        fail("the mistake is in cells %s, the first fix names cell %d" % (differ, number))
    report = open(os.path.join(out, "report.md")).read()
    if m.group(0) not in report:
        fail("report.md does not name %s" % m.group(0))
    for tb in re.findall(r'File "([^"]+)", line \d+', report):
        if "cell" not in tb:
            fail("a traceback names a file, not a cell: " + tb)
    print("first fix: %s (cell %d, In [%s], line %d): the cell of the one mistake" % (slot, number, count, line))


def correct(geomech, out, notebook, options):
    r = check(geomech, notebook, out, options)
    if r.returncode != 0:
        fail("%s: exit %d, expected 0\n%s%s" % (notebook, r.returncode, r.stdout, r.stderr))
    report = open(os.path.join(out, "report.md")).read()
    said = re.search(r"^Notebook: (.*)$", report, re.M)
    if not said or "**Result: PASS**" not in report:
        fail("report.md has no Notebook: line or no PASS:\n" + report[:2000])
    said = said.group(1)
    nb = nbformat.read(notebook, as_version=4)
    shown = [str(i + 1) for i, c in enumerate(nb.cells) if c.cell_type != "code"]
    words = "cell " + shown[0] if len(shown) == 1 else "cells " + ", ".join(shown[:-1]) + " and " + shown[-1]
    if words + " (Markdown or raw" not in said:
        fail("the Markdown cells are %s; the report says: %s" % (words, said))
    code = [i + 1 for i, c in enumerate(nb.cells) if c.cell_type == "code"]
    tagged = [i + 1 for i, c in enumerate(nb.cells) if "skip-execution" in c.metadata.get("tags", [])]
    magic = [i + 1 for i, c in enumerate(nb.cells) if c.cell_type == "code" and c.source.startswith("%%")]
    escape = [(i + 1, n + 1) for i, c in enumerate(nb.cells) if c.cell_type == "code"
              for n, text in enumerate(c.source.split("\n")) if text.startswith("!")]
    runs = len(code) - len(tagged) - len(magic)
    for want in ["its %d code cells are the implementation" % runs,
                 "cell %d (tagged skip-execution" % tagged[0],
                 "cell %d, In [%d] (a cell magic" % (magic[0], nb.cells[magic[0] - 1].execution_count),
                 "cell %d, In [%d], line %d (a shell escape" % (escape[0][0], nb.cells[escape[0][0] - 1].execution_count,
                                                               escape[0][1])]:
        if want not in said:
            fail("the report's Notebook: line does not say %r: %s" % (want, said))
    print("correct: PASS; " + said)


def cell_fails(geomech, out):
    os.makedirs(out, exist_ok=True)
    python = {"kernelspec": {"name": "python3", "language": "python", "display_name": "Python 3"}}
    octave = {"kernelspec": {"name": "octave", "language": "octave", "display_name": "Octave"}}
    py_casimir = "def casimir(Pi):\n    return sum(p * p for p in Pi) / 2"
    m_casimir = "function r = casimir(Pi)\n  r = sum(Pi .^ 2) / 2;\nend"
    # (name, kernel, the first code cell, the third cell (the one that fails: its line 2), what the
    # traceback or the interpreter's message says of that line)
    cases = [
        ("raises", python, py_casimir, "x = casimir([1, 2, 3])\ny = undefined_name + x",
         ['File "raises.ipynb, cell 3, In [4]", line 2', "NameError"]),
        ("syntax", python, py_casimir, "x = 1\ny = (x + ",
         ['File "syntax.ipynb, cell 3, In [4]", line 2', "SyntaxError"]),
        ("raises_octave", octave, m_casimir, "x = casimir([1; 2; 3]);\ny = undefined_name + x;",
         ["at line 2 (raises_octave.ipynb, cell 3, In [4])", "'undefined_name' undefined"]),
        ("syntax_octave", octave, m_casimir, "x = 1;\ny = (x + ;",
         ["parse error near line 2 of file syntax_octave.ipynb, cell 3, In [4]"]),
    ]
    for name, kernel, first, failing, says in cases:
        nb = nbformat.v4.new_notebook(metadata=kernel)
        nb.cells = [nbformat.v4.new_markdown_cell("# raises"),
                    nbformat.v4.new_code_cell(first, execution_count=1),
                    nbformat.v4.new_code_cell(failing, execution_count=4)]
        path = os.path.join(out, name + ".ipynb")
        nbformat.write(nb, path)
        r = check(geomech, path, os.path.join(out, "report-" + name), [])
        said = r.stderr
        if r.returncode != 2 or name + ".ipynb, cell 3, In [4] failed when run" not in said:
            fail("%s: expected exit 2 naming cell 3, In [4]: exit %d\n%s" % (name, r.returncode, said))
        for want in says:
            if want not in said:
                fail("%s: the message does not name line 2 of cell 3 (%r):\n%s" % (name, want, said))
        print("cell_fails: %s: %s" % (name, said.strip().splitlines()[0][:200]))


def malformed(geomech, out):
    os.makedirs(out, exist_ok=True)
    good = nbformat.v4.new_notebook(metadata={"kernelspec": {"name": "python3", "language": "python",
                                                             "display_name": "Python 3"}})
    good.cells = [nbformat.v4.new_markdown_cell("# x"), nbformat.v4.new_code_cell("def casimir(Pi):\n    return 0")]
    base = json.loads(nbformat.writes(good))

    def variant(change):
        j = json.loads(json.dumps(base))
        change(j)
        return json.dumps(j)

    cases = [
        ("not_json", '{"cells": [', "is not a notebook: its JSON does not parse", True),
        ("nbformat3", variant(lambda j: j.update(nbformat=3)), "it is written in nbformat 3", True),
        ("no_cells", variant(lambda j: j.pop("cells")), 'its "cells" is missing', True),
        ("source_number", variant(lambda j: j["cells"][1].update(source=7)),
         'cell 2: its "source" is a number', True),
        ("no_cell_type", variant(lambda j: j["cells"][0].pop("cell_type")), 'cell 1: its "cell_type" is missing', True),
        ("count_text", variant(lambda j: j["cells"][1].update(execution_count="three")),
         'cell 2: its "execution_count" is a text', True),
        ("no_kernel", variant(lambda j: j["metadata"].pop("kernelspec")), "its metadata names no kernel", False),
        ("julia", variant(lambda j: j["metadata"]["kernelspec"].update(name="julia-1.9", language="julia")),
         "its kernel is 'julia'", False),
    ]
    for name, text, expect, invalid in cases:
        path = os.path.join(out, name + ".ipynb")
        with open(path, "w") as f:
            f.write(text)
        r = check(geomech, path, os.path.join(out, name), [])
        if r.returncode != 2 or (name + ".ipynb: " not in r.stderr and name + ".ipynb is not" not in r.stderr) \
                or expect not in r.stderr:
            fail("%s: expected exit 2 saying %r: exit %d\n%s" % (name, expect, r.returncode, r.stderr))
        if invalid:  # the format's own library agrees it is broken
            try:
                nbformat.validate(nbformat.reads(text, as_version=nbformat.NO_CONVERT))
                fail("%s: nbformat finds it valid" % name)
            except (nbformat.ValidationError, ValueError, KeyError, AttributeError, TypeError):
                pass
            except Exception as e:  # nbformat's own errors for a version it does not read
                if "nbformat" not in type(e).__module__ and "json" not in type(e).__module__:
                    raise
        print("%s: %s" % (name, r.stderr.strip().splitlines()[-1][:160]))


def klass(geomech, examples, out, class_py, options):
    shutil.rmtree(out, ignore_errors=True)
    folder = os.path.join(out, "class")
    os.makedirs(os.path.join(folder, "bob"))
    shutil.copy(os.path.join(examples, "week3.ipynb"), os.path.join(folder, "alice.ipynb"))
    shutil.copy(os.path.join(examples, "bug_week3_octave.ipynb"), os.path.join(folder, "bob", "week3.ipynb"))
    with open(os.path.join(folder, "carol.ipynb"), "w") as f:
        f.write('{"cells": [')
    shutil.copy(class_py, os.path.join(folder, "dave.py"))
    r = subprocess.run([geomech, "check-class", folder, "--report", os.path.join(out, "reports"),
                        "--feedback-dir", os.path.join(out, "feedback")] + options, capture_output=True, text=True)
    if r.returncode != 1:
        fail("check-class: exit %d, expected 1 (bob fails)\n%s%s" % (r.returncode, r.stdout, r.stderr))
    summary = open(os.path.join(out, "reports", "summary.md")).read()
    for name, result in [("alice", "| PASS |"), ("bob", "| **FAIL** |"), ("carol", "| **NOT CHECKED** |"),
                         ("dave", "| PASS |")]:
        row = re.search(r"^\| %s \|.*$" % name, summary, re.M)
        if not row or result not in row.group(0):
            fail("the row of %s does not say %s: %s" % (name, result, row.group(0) if row else summary))
    for said in ["**alice** (Python notebook): PASS", "**bob** (Octave notebook): FAIL",
                 "carol.ipynb is not a notebook: its JSON does not parse"]:
        if said not in summary:
            fail("summary.md does not say %r" % said)
    m = re.search(r"first fix: Octave function 'omega_3_5' in week3.ipynb \((cell (\d+), In \[(\d+)\], line (\d+))\)",
                  summary)
    if not m:
        fail("bob's first fix names no cell:\n" + summary)
    nb = nbformat.read(os.path.join(folder, "bob", "week3.ipynb"), as_version=4)
    cell = nb.cells[int(m.group(2)) - 1]
    if cell.execution_count != int(m.group(3)) or not defines(cell.source.split("\n")[int(m.group(4)) - 1], "omega_3_5"):
        fail("bob's %s does not define omega_3_5" % m.group(1))
    page = open(os.path.join(out, "feedback", "bob.html")).read()
    if m.group(1) not in page:
        fail("bob's feedback page does not name %s" % m.group(1))
    print("class: alice PASS, bob FAIL (first fix omega_3_5, %s), carol not checked (not JSON), dave PASS" % m.group(1))


def main(argv):
    if len(argv) < 4:
        sys.exit(__doc__)
    geomech, examples, out, case = argv[:4]
    rest = argv[4:]
    if case == "first_fix":
        first_fix(geomech, out, os.path.join(examples, rest[0]), os.path.join(examples, rest[1]), rest[2], rest[3:])
    elif case == "correct":
        correct(geomech, out, os.path.join(examples, rest[0]), rest[1:])
    elif case == "cell_fails":
        cell_fails(geomech, out)
    elif case == "malformed":
        malformed(geomech, out)
    elif case == "class":
        klass(geomech, examples, out, rest[0], rest[1:])
    else:
        sys.exit(__doc__)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
