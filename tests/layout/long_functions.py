#!/usr/bin/env python3
"""Lists the functions of 100 lines or more (docs/DEVELOPING.md, "Layout": functions a reader can
hold, each step of a long one a function of its own, named).

    python3 tests/layout/long_functions.py [ROOT] [--min N]

A function is a line that starts a declaration at the left margin and opens a brace-balanced body;
its length runs from that line to its closing brace (lambdas inside count towards it). Inputs of
checks and tests (examples/, tests/class/, the layout and unity controls) and build trees are left
out. Prints one line per function, longest first, and the count; always exits 0: a report, not a
test.
"""
import glob
import os
import re
import sys

LEFT_OUT = ("build", "examples", "tests/class", "tests/layout/controls", "tests/unity/controls")
NOT_A_FUNCTION = ("namespace", "struct", "class", "enum", "using", "#", "//", "static_assert", "template",
                  "TEST", "GM_")


def long_functions(root, least):
    found = []
    files = glob.glob(os.path.join(root, "**/*.cpp"), recursive=True) + \
        glob.glob(os.path.join(root, "**/*.hpp"), recursive=True)
    for path in files:
        rel = os.path.relpath(path, root)
        if rel.startswith(LEFT_OUT):
            continue
        lines = open(path, errors="replace").read().split("\n")
        i = 0
        while i < len(lines):
            line = lines[i]
            m = re.match(r"^([A-Za-z].*?)\b([A-Za-z_][A-Za-z_0-9:]*)\(", line)
            if m and not line.startswith(NOT_A_FUNCTION) and not line.rstrip().endswith(";"):
                j = i
                while j < len(lines) and "{" not in lines[j] and not lines[j].rstrip().endswith(";"):
                    j += 1
                if j < len(lines) and lines[j].rstrip().endswith("{"):
                    depth, k = 0, j
                    for k in range(j, len(lines)):
                        depth += lines[k].count("{") - lines[k].count("}")
                        if depth == 0:
                            break
                    if k - i + 1 >= least:
                        found.append((k - i + 1, rel, i + 1, m.group(2)))
                    i = k + 1
                    continue
            i += 1
    return sorted(found, reverse=True)


def main():
    args = [a for a in sys.argv[1:]]
    least = 100
    if "--min" in args:
        at = args.index("--min")
        least = int(args[at + 1])
        del args[at:at + 2]
    root = args[0] if args else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
    found = long_functions(os.path.abspath(root), least)
    for n, rel, line, name in found:
        print("%4d  %s:%d  %s" % (n, rel, line, name))
    print("%d functions of %d lines or more" % (len(found), least))


if __name__ == "__main__":
    main()
