#!/usr/bin/env python3
"""Checks that every file compiled in a unity batch also compiles alone (its own includes suffice).

In a unity batch (CMakeLists.txt, GEOMECH_UNITY_BUILD) a file sees everything the files before it
included: one that forgot an #include compiles there and fails the day it is compiled alone (with
-DGEOMECH_UNITY_BUILD=OFF, or in another batch). Compiling every file alone again would cost as
much as the build the batches save (measured: 240 CPU-s of `-fsyntax-only` for the 53 files), so
each file is parsed alone instead: its batch's own compile command (flags, definitions, the
precompiled header) with `-fsyntax-only` and tests/unity/parse_only.hpp, which turns the
registrations (GM_PROPERTY, GM_MUTANT, ...) into nothing, so that no property body is instantiated
for a scalar (27 CPU-s for the 53 files). A name the file uses without declaring it is an error at
its definition, as in a full compile: every qualified name (std::map, dyn::energy, truth::cross),
every type and every non-dependent call. What parsing alone does not see is an unqualified call
whose arguments depend on the scalar, looked up at instantiation; the hygiene rules
(tests/unity/hygiene.py: each file in a namespace of its own) keep such a call from binding to
another file's helper.

Usage: compiles_alone.py BUILD_DIR TARGET FILE...
  BUILD_DIR  a build tree configured with CMAKE_EXPORT_COMPILE_COMMANDS (compile_commands.json)
  TARGET     the CMake target whose unity batches lend their command (geomech, geomech_mutants)
Prints `FILE: compiles alone` or the compiler's first errors, and a summary line; exits 1 if any
file does not compile alone.
"""
import concurrent.futures
import json
import os
import re
import shlex
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def batch_command(build_dir, target):
    """The compile command (argv list and directory) of one unity batch of `target`."""
    with open(os.path.join(build_dir, "compile_commands.json"), encoding="utf-8") as f:
        entries = json.load(f)
    pattern = re.compile(r"/CMakeFiles/" + re.escape(target) + r"\.dir/Unity/unity_\d+_cxx\.cxx$")
    for e in entries:
        if pattern.search(e["file"]):
            argv = e["arguments"] if "arguments" in e else shlex.split(e["command"])
            return argv, e["directory"]
    sys.exit(f"compiles_alone.py: no unity batch of target '{target}' in {build_dir}/compile_commands.json "
             "(is this a unity build?)")


def alone(argv, directory, path):
    """argv with its output and source replaced: parse `path` alone."""
    out, skip = [], False
    for a in argv:
        if skip:
            skip = False
            continue
        if a in ("-o", "-c"):
            skip = True
            continue
        out.append(a)
    return out + ["-fsyntax-only", "-include", os.path.join(HERE, "parse_only.hpp"), "-c", path], directory


def check(argv, directory, path):
    cmd, cwd = alone(argv, directory, path)
    r = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    errors = [line for line in r.stdout.splitlines() if "error" in line]
    return path, r.returncode == 0, "\n".join(errors[:6]) if errors else r.stdout[-2000:]


def main(args):
    if len(args) < 3:
        sys.exit(__doc__)
    build_dir, target, files = args[0], args[1], args[2:]
    argv, directory = batch_command(build_dir, target)
    jobs = max(1, min(len(files), int(os.environ.get("GEOMECH_JOBS", os.cpu_count() or 1))))
    bad = 0
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        for path, ok, text in pool.map(lambda p: check(argv, directory, p), files):
            if ok:
                print(f"{path}: compiles alone")
            else:
                bad += 1
                print(f"{path}: does not compile alone (it relies on an #include of a file before it in its unity batch, "
                      f"or is wrong):\n{text}")
    print(f"compiles alone: {len(files)} files, {bad} problems")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
