#!/usr/bin/env python3
"""Writes the example notebooks of examples/students/ (a week-3 notebook as a course hands them in),
with nbformat, the Jupyter notebook format's own library (Debian: python3-nbformat):

    /usr/bin/python3 examples/students/notebooks.py [FOLDER]     (default: this file's folder)

  week3.ipynb            Python kernel, correct: the hat map, Omega (3.5), Euler (3.8), h (3.4), C
  bug_week3.ipynb        the same with one mistake: Euler's (3.8) as Omega x Pi, in cell 6
  week3_octave.ipynb     Octave kernel, correct: the same slots as MATLAB functions
  bug_week3_octave.ipynb the same with one mistake: Omega (3.5) as I .* Pi, in cell 6, which
                         euler_3_8 calls

Each holds what a course notebook holds besides the functions, and geomech sets aside (and says
so): Markdown cells, a cell magic (%%time), a shell escape (!pip ...), a line magic (%matplotlib),
a cell tagged skip-execution (a plot). Execution counts are those of a run from the top, as a
student saves them. The one-mistake notebooks differ from the correct ones in one cell
(tests/notebooks.py checks that the first fix names it).
"""
import os
import sys

import nbformat
from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook

PYTHON_KERNEL = {"display_name": "Python 3 (ipykernel)", "language": "python", "name": "python3"}
OCTAVE_KERNEL = {"display_name": "Octave", "language": "octave", "name": "octave"}

PY_EULER = """def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def omega_3_5(I, Pi):
    return [p / i for p, i in zip(Pi, I)]


def euler_3_8(I, Pi):
    return cross(Pi, omega_3_5(I, Pi))"""


def python_notebook(euler):
    cells = [
        new_markdown_cell("# Week 3: the free rigid body\n\nEach function is named after its slot "
                          "(`geomech slots --python`), and written for any number type: float, "
                          "mpmath's and fractions' (no `math.sqrt`, no `0.5`)."),
        new_code_cell("%matplotlib inline\nfrom fractions import Fraction"),
        new_markdown_cell("## The hat map (2.11)"),
        new_code_cell("def hat(v):\n    z = 0 * v[0]\n    return [[z, -v[2], v[1]], [v[2], z, -v[0]], [-v[1], v[0], z]]"
                      "\n\n\ndef vee(m):\n    return [m[2][1], m[0][2], m[1][0]]"),
        new_markdown_cell("## Euler's equations (3.8): $\\dot\\Pi = \\Pi \\times \\Omega$, $\\Omega = I^{-1}\\Pi$"),
        new_code_cell(euler),
        new_code_cell("def hamiltonian_3_4(I, Pi):\n    return sum(p * w for p, w in zip(Pi, omega_3_5(I, Pi))) / 2"
                      "\n\n\ndef casimir(Pi):\n    return sum(p * p for p in Pi) / 2"),
        new_code_cell("!pip install mpmath\nI = [Fraction(2), Fraction(1), Fraction(2, 3)]\n"
                      "print(hamiltonian_3_4(I, [1, 0, 1]), casimir([1, 0, 1]))"),
        new_code_cell("%%time\nfor k in range(1000):\n    euler_3_8([2, 1, 3], [1, 2, 3])"),
        new_code_cell("import matplotlib.pyplot as plt\nplt.plot([casimir([k, 0, 1]) for k in range(10)])",
                      metadata={"tags": ["skip-execution"]}),
    ]
    return cells


OC_EULER = """function W = omega_3_5(I, Pi)
  W = Pi ./ I;
end

function d = euler_3_8(I, Pi)
  d = cross(Pi, omega_3_5(I, Pi));
end"""


def octave_notebook(euler):
    cells = [
        new_markdown_cell("# Week 3: the free rigid body, in Octave\n\nEach function is named after its slot "
                          "(`geomech slots --octave`); vectors are columns."),
        new_code_cell("%plot inline\nformat long"),
        new_markdown_cell("## The hat map (2.11)"),
        new_code_cell("function m = hat(v)\n  m = [0, -v(3), v(2); v(3), 0, -v(1); -v(2), v(1), 0];\nend\n\n"
                      "function v = vee(m)\n  v = [m(3, 2); m(1, 3); m(2, 1)];\nend"),
        new_markdown_cell("## Euler's equations (3.8)"),
        new_code_cell(euler),
        new_code_cell("function h = hamiltonian_3_4(I, Pi)\n  h = dot(Pi, omega_3_5(I, Pi)) / 2;\nend\n\n"
                      "function c = casimir(Pi)\n  c = dot(Pi, Pi) / 2;\nend"),
        new_code_cell("!ls\nI = [2; 1; 2/3];\ndisp([hamiltonian_3_4(I, [1; 0; 1]), casimir([1; 0; 1])])"),
        new_code_cell("%%file notes.txt\nwritten by the Octave kernel, not run by Octave"),
        new_code_cell("plot(arrayfun(@(k) casimir([k; 0; 1]), 0:9))", metadata={"tags": ["skip-execution"]}),
    ]
    return cells


def write(folder, name, cells, kernel, language_info):
    nb = new_notebook(cells=cells, metadata={"kernelspec": kernel, "language_info": language_info})
    count = 0
    for i, c in enumerate(nb.cells, 1):
        c.id = "cell-%d" % i  # not random: the notebooks are written again the same  # run from the top, as a student saves it; a skipped cell was not run
        if c.cell_type == "code" and "skip-execution" not in c.metadata.get("tags", []):
            count += 1
            c.execution_count = count
    nbformat.validate(nb)
    nbformat.write(nb, os.path.join(folder, name))


def main(argv):
    folder = argv[0] if argv else os.path.dirname(os.path.abspath(__file__))
    py_info = {"name": "python", "version": "3.11.2", "file_extension": ".py", "mimetype": "text/x-python"}
    oc_info = {"name": "octave", "version": "7.3.0", "file_extension": ".m", "mimetype": "text/x-octave"}
    write(folder, "week3.ipynb", python_notebook(PY_EULER), PYTHON_KERNEL, py_info)
    # The one mistake: the cross product reversed, dPi/dt = Omega x Pi.
    write(folder, "bug_week3.ipynb", python_notebook(PY_EULER.replace("cross(Pi, omega_3_5(I, Pi))",
                                                                      "cross(omega_3_5(I, Pi), Pi)")),
          PYTHON_KERNEL, py_info)
    write(folder, "week3_octave.ipynb", octave_notebook(OC_EULER), OCTAVE_KERNEL, oc_info)
    # The one mistake: the inertia multiplied instead of divided, Omega = I .* Pi.
    write(folder, "bug_week3_octave.ipynb", octave_notebook(OC_EULER.replace("W = Pi ./ I;", "W = I .* Pi;")),
          OCTAVE_KERNEL, oc_info)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
