#!/usr/bin/env python3
"""Checks that nothing outside the language table and the servers asks which language it is
talking to (docs/DEVELOPING.md, "Adding a language"): a language is a row of the table
(harness/languages/), and a file that compares a language id ("python", "octave") or names an
enumerator after a language (ShowStyle::Python) would be one more place a new row has to be added.

    language_ids.py ROOT GEOMECH     GEOMECH: the built tool, whose `geomech languages --ids` gives
                                     the table's ids and names, one row a line ("python Python")

In every C++ source of ROOT (but build trees, tests/, the table's room harness/languages/ and the
servers under student/), outside // comments, it finds:
  - an id's string literal compared (== "python", "octave" !=, .compare("python"), .count("octave"),
    .find("c++"), .insert("python"), a starts_with or ends_with of one) or looked up by its literal
    (language_named("octave"));
  - an enumerator named after a row (::Python, ::Octave).
Prints `FILE:LINE: what` per finding, then a summary; exit 1 if any.
"""
import os
import re
import subprocess
import sys

SOURCE = (".cpp", ".hpp", ".h", ".cc")
ALLOWED = ("harness/languages/", "student/", "tests/")


def table(geomech):
    out = subprocess.run([geomech, "languages", "--ids"], check=True, capture_output=True, text=True).stdout
    rows = [line.split(None, 1) for line in out.splitlines() if line.strip()]
    return [r[0] for r in rows], [r[1].strip() for r in rows if len(r) > 1]


def patterns(ids, names):
    out = []
    for i in ids:
        lit = re.escape('"' + i + '"')
        out.append((re.compile(r"(==|!=)\s*" + lit + r"|" + lit + r"\s*\)?\s*(==|!=)"), f'compares the id "{i}"'))
        out.append((re.compile(r"\.(compare|count|find|contains|insert|starts_with|ends_with)\(\s*" + lit),
                    f'compares the id "{i}"'))
        out.append((re.compile(r"\blanguage_named\(\s*" + lit), f'looks the row "{i}" up by its id'))
    for n in names:
        if re.fullmatch(r"[A-Za-z_]\w*", n):
            out.append((re.compile(r"::" + re.escape(n) + r"\b(?!\s*\()"), f"an enumerator named after {n}"))
    return out


def code_of(line):
    """The line without a // comment (a // inside a string literal is kept)."""
    quote = None
    i = 0
    while i < len(line):
        c = line[i]
        if quote:
            if c == "\\":
                i += 1
            elif c == quote:
                quote = None
        elif c in "\"'":
            quote = c
        elif line.startswith("//", i):
            return line[:i]
        i += 1
    return line


def sources(root):
    for folder, dirs, files in os.walk(root):
        rel = os.path.relpath(folder, root).replace(os.sep, "/")
        dirs[:] = sorted(d for d in dirs if not d.startswith((".", "build")))
        for name in sorted(files):
            path = name if rel == "." else f"{rel}/{name}"
            if name.endswith(SOURCE) and not path.startswith(ALLOWED):
                yield path


def main(argv):
    if len(argv) != 2:
        sys.exit(__doc__)
    root, geomech = argv
    ids, names = table(geomech)
    checks = patterns(ids, names)
    found = []
    count = 0
    for path in sources(root):
        count += 1
        with open(os.path.join(root, path), encoding="utf-8", errors="replace") as f:
            for n, line in enumerate(f, 1):
                code = code_of(line)
                for pattern, what in checks:
                    if pattern.search(code):
                        found.append(f"{path}:{n}: {what}: {line.strip()}")
    for f in found:
        print(f)
    print(f"language ids: {len(ids)} languages ({', '.join(ids)}), {count} files, {len(found)} problems")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
