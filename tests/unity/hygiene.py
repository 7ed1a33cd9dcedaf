#!/usr/bin/env python3
"""Checks that files compiled together in a unity batch cannot see each other's names.

CMake's unity build (CMakeLists.txt, GEOMECH_UNITY_BUILD) compiles up to 8 property files (or
mutant files) as one translation unit. Without care a helper of one file, or its anonymous
namespace, is visible to the next: a clash is a compile error, but an overload of a different
signature is not, and a call could silently bind to the other file's helper. So every file of a
batch keeps its code in a namespace of its own, and its macros end with it:

  1. every `namespace gm {` is followed by `namespace <folder>_<file> {` (for instance
     `namespace properties_variations {` in properties/variations/variations.cpp), and that namespace
     closes just before `}  // namespace gm`. <folder> is the nearest enclosing folder named
     `properties` or `mutants` (a part folder such as properties/s3_4_nambu/ does not change the
     name, so a file keeps its namespace when it moves between parts), else the file's own folder;
     file names are unique across those trees, so the names are too;
  2. there is no code outside `namespace gm { ... }` (only comments and preprocessor lines);
  3. every macro the file #defines is #undef'd in the same file.

Usage: hygiene.py FILE...   Prints `FILE:LINE: what is wrong` per problem and exits 1 if any.
"""
import os
import re
import sys


def unit_namespace(path):
    parts = os.path.dirname(os.path.abspath(path)).split(os.sep)
    roots = [p for p in parts if p in ("properties", "mutants")]
    folder = roots[-1] if roots else parts[-1]
    stem = os.path.splitext(os.path.basename(path))[0]
    return f"{folder}_{stem}"


def problems_in(path):
    ns = unit_namespace(path)
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    found = []
    inside = False
    opened = 0
    defined, undefined = {}, set()
    in_block_comment = False
    for i, line in enumerate(lines, 1):
        stripped = line.strip()
        m = re.match(r"#\s*define\s+(\w+)", stripped)
        if m:
            defined.setdefault(m.group(1), i)
        m = re.match(r"#\s*undef\s+(\w+)", stripped)
        if m:
            undefined.add(m.group(1))
        if in_block_comment:
            in_block_comment = "*/" not in line
            continue
        if stripped.startswith("/*"):
            in_block_comment = "*/" not in stripped
            continue
        if line == "namespace gm {":
            if inside:
                found.append((i, "`namespace gm {` opened twice"))
            inside = True
            opened += 1
            nxt = lines[i] if i < len(lines) else ""
            if nxt != f"namespace {ns} {{":
                found.append((i + 1, f"`namespace gm {{` must be followed by `namespace {ns} {{` (this file's own "
                                     "namespace in a unity batch)"))
            continue
        if line == "}  // namespace gm":
            prev = lines[i - 2] if i >= 2 else ""
            if prev != f"}}  // namespace {ns}":
                found.append((i - 1, f"`}}  // namespace {ns}` must close just before `}}  // namespace gm`"))
            inside = False
            continue
        if not inside and stripped and not stripped.startswith("//") and not stripped.startswith("#"):
            found.append((i, f"code outside `namespace gm {{ namespace {ns} {{ ... }} }}`: {stripped[:60]}"))
    if opened == 0:
        found.append((1, f"no `namespace gm {{ namespace {ns} {{`"))
    for name, line_no in sorted(defined.items(), key=lambda kv: kv[1]):
        if name not in undefined:
            found.append((line_no, f"macro {name} is #defined but never #undef'd: it would leak into the next "
                                   "file of the unity batch"))
    return found


def main(paths):
    if not paths:
        print("hygiene.py: no files given (expected the unity-built sources)", file=sys.stderr)
        return 2
    bad = 0
    seen = {}
    for p in paths:
        ns = unit_namespace(p)
        if ns in seen:
            print(f"{p}:1: namespace {ns} is also {seen[ns]}'s: two files of one tree share a name")
            bad += 1
        seen.setdefault(ns, p)
    for p in paths:
        for line_no, what in problems_in(p):
            print(f"{p}:{line_no}: {what}")
            bad += 1
    print(f"unity hygiene: {len(paths)} files, {bad} problems")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
