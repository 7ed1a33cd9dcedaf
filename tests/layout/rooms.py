#!/usr/bin/env python3
"""Checks that no file includes a room above its own (docs/DEVELOPING.md, "Layout").

A room is a folder whose README.md has a line

    May include: harness/checking, harness/isolation

naming the other rooms its files may include (`May include: no other room.` for none). A file
belongs to the innermost room above it. Its `#include "a/b.hpp"` lines are root-relative; one that
names a file of another room must name a room on that list. A file that is in no room but lies in
the folder holding some rooms (properties/support/, properties/runner.hpp, tests/mutants/mutants.hpp)
is the base they stand on and may include none of them. The rooms' lists must not go round in a
circle, and every folder of a tree that holds rooms (harness/*, properties/*, tests/mutants/*, but
support/) must be a room, so a new folder cannot escape the check.

The top level is held the same way, one floor up: every folder of ROOT that holds C++ sources (but a
build tree) is a top-level room whose README.md has a line

    Top level may include: core, impl, properties

and an include that crosses from one top-level room into another must name a room on that list; the
lists must not go round in a circle either. tests/mutants/ is a top-level room of its own, with the
same line (the negative controls, built into the suite's library and read by mutation/ and tools/,
stand apart from tests/, which may include everything). Inside one
top-level room, the rooms above apply.

Usage: rooms.py ROOT   Prints `FILE:LINE: what is wrong` per problem, then a summary; exit 1 if any.
"""
import os
import re
import sys

TREES = ("harness", "properties", "tests/mutants")
INCLUDE = re.compile(r'\s*#\s*include\s+"([^"]+)"')
MAY = re.compile(r"^May include:\s*(.*)$")
NESTED_TOPS = ("tests/mutants",)  # top-level rooms that lie inside another one
TOP = re.compile(r"^Top level may include:\s*(.*)$")
SOURCE = (".cpp", ".hpp")


def declared(readme, pattern, is_room):
    """The rooms a README.md's line matching `pattern` names (the words `is_room` accepts: a room
    list reads "no other room." for none), or None when it has no such line."""
    if os.path.isfile(readme):
        with open(readme, encoding="utf-8") as f:
            for line in f:
                m = pattern.match(line.strip())
                if m:
                    return {w for w in (w.strip().rstrip(".") for w in m.group(1).split(",")) if w and is_room(w)}
    return None


def read_rooms(root):
    """{room folder: set of rooms it may include}, and problems with the declarations."""
    rooms, problems = {}, []
    for tree in TREES:
        top = os.path.join(root, tree)
        if not os.path.isdir(top):
            continue
        for name in sorted(os.listdir(top)):
            folder = f"{tree}/{name}"
            if not os.path.isdir(os.path.join(root, folder)) or name == "support":
                continue
            allowed = declared(os.path.join(root, folder, "README.md"), MAY, lambda w: "/" in w)
            if allowed is None:
                problems.append((f"{folder}/README.md", 1, "no `May include:` line: every folder of "
                                 f"{tree}/ is a room that says which rooms it may include"))
                continue
            rooms[folder] = allowed
    for folder, allowed in rooms.items():
        for other in sorted(allowed):
            if other not in rooms:
                problems.append((f"{folder}/README.md", 1, f"`May include:` names {other}, which is not a room"))
    return rooms, problems


def circle(rooms):
    """A list of rooms that include each other round a circle, or None."""
    state = {}

    def visit(room, path):
        state[room] = "open"
        for other in sorted(rooms.get(room, ())):
            if state.get(other) == "open":
                return path[path.index(other):] + [other]
            if other not in state:
                found = visit(other, path + [other])
                if found:
                    return found
        state[room] = "done"
        return None

    for room in sorted(rooms):
        if room not in state:
            found = visit(room, [room])
            if found:
                return found
    return None


def room_of(path, rooms):
    best = None
    for room in rooms:
        if path.startswith(room + "/") and (best is None or len(room) > len(best)):
            best = room
    return best


def sources(root):
    for tree in TREES:
        for folder, dirs, files in os.walk(os.path.join(root, tree)):
            dirs.sort()
            for name in sorted(files):
                if name.endswith((".cpp", ".hpp")):
                    yield os.path.relpath(os.path.join(folder, name), root).replace(os.sep, "/")


def holds_sources(folder):
    for _, dirs, files in os.walk(folder):
        if any(name.endswith(SOURCE) for name in files):
            return True
    return False


def read_top_rooms(root):
    """{top-level room: set of top-level rooms it may include}, and problems with the declarations."""
    tops, problems = {}, []
    for name in sorted(os.listdir(root)):
        folder = os.path.join(root, name)
        if name.startswith(".") or not os.path.isdir(folder) or os.path.exists(os.path.join(folder, "CMakeCache.txt")):
            continue
        if not holds_sources(folder):
            continue
        allowed = declared(os.path.join(folder, "README.md"), TOP, lambda w: " " not in w)
        if allowed is None:
            problems.append((f"{name}/README.md", 1, "no `Top level may include:` line: every top-level folder "
                             "holding C++ sources is a room that says which others it may include"))
            continue
        tops[name] = allowed
    for nested in NESTED_TOPS:
        found = declared(os.path.join(root, nested, "README.md"), TOP, lambda w: " " not in w)
        if found is not None:
            tops[nested] = found
        elif os.path.isdir(os.path.join(root, nested)):
            problems.append((f"{nested}/README.md", 1, "no `Top level may include:` line: it is a top-level room "
                             "of its own"))
    for room, allowed in tops.items():
        for other in sorted(allowed):
            if other not in tops:
                problems.append((f"{room}/README.md", 1, f"`Top level may include:` names {other}, which is not a "
                                 "top-level room"))
    return tops, problems


def top_sources(root, tops):
    for room in sorted(t for t in tops if "/" not in t):
        for folder, dirs, files in os.walk(os.path.join(root, room)):
            dirs.sort()
            for name in sorted(files):
                if name.endswith(SOURCE):
                    yield os.path.relpath(os.path.join(folder, name), root).replace(os.sep, "/")


def main(argv):
    if len(argv) != 1:
        print("usage: rooms.py ROOT", file=sys.stderr)
        return 2
    root = argv[0]
    rooms, problems = read_rooms(root)
    found = circle(rooms)
    if found:
        problems.append((f"{found[0]}/README.md", 1, "the rooms include each other round a circle: "
                         + " -> ".join(found)))
    tops, top_problems = read_top_rooms(root)
    problems += top_problems
    found = circle(tops)
    if found:
        problems.append((f"{found[0]}/README.md", 1, "the top-level rooms include each other round a circle: "
                         + " -> ".join(found)))
    files = includes = crossing = 0
    inner = set(sources(root))
    for path in sorted(inner | set(top_sources(root, tops))):
        files += path in inner
        mine = room_of(path, rooms)
        mine_top = room_of(path, tops)
        with open(os.path.join(root, path), encoding="utf-8") as f:
            for line_no, line in enumerate(f, 1):
                m = INCLUDE.match(line)
                if not m:
                    continue
                target = m.group(1)
                theirs_top = room_of(target, tops)
                if mine_top is not None and theirs_top is not None and theirs_top != mine_top:
                    crossing += 1
                    if theirs_top not in tops[mine_top]:
                        allowed = ", ".join(sorted(tops[mine_top])) or "no other room"
                        problems.append((path, line_no, f"includes {target} of the top-level room {theirs_top}, "
                                         f"which {mine_top}/README.md does not list (Top level may include: {allowed})"))
                    continue
                if path not in inner:
                    continue
                includes += 1
                theirs = room_of(target, rooms)
                if theirs is None or theirs == mine:
                    continue
                if mine is None:
                    holder = os.path.dirname(theirs)
                    if path.startswith(holder + "/"):
                        problems.append((path, line_no, f"includes {target} of the room {theirs}: a file "
                                         f"that {holder}/'s rooms stand on may include none of them"))
                elif theirs not in rooms[mine]:
                    allowed = ", ".join(sorted(rooms[mine])) or "no other room"
                    problems.append((path, line_no, f"includes {target} of the room {theirs}, which "
                                     f"{mine}/README.md does not list (May include: {allowed})"))
    for path, line_no, what in problems:
        print(f"{path}:{line_no}: {what}")
    print(f"layout: {len(rooms)} rooms, {files} files, {includes} includes, {len(problems)} problems; "
          f"top level: {len(tops)} rooms, {crossing} includes between them")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
