#!/usr/bin/env python3
"""Every test's cost, from the JUnit file of a ctest run (ctest --output-junit FILE):

    ctest --test-dir build -j2 --output-junit /tmp/ctest.xml
    bench/test_costs.py /tmp/ctest.xml [N]
    bench/test_costs.py --time-of TEST /tmp/ctest.xml    # one test's seconds alone (nothing if absent)
    bench/test_costs.py --cost-data /tmp/ctest.xml > tests/ctest_costs.txt

--cost-data writes ctest's own cost file (Testing/Temporary/CTestCostData.txt: "NAME RUNS SECONDS"
a line) for the tests of at least 0.5 s, costliest first. tests/CMakeLists.txt copies
tests/ctest_costs.txt there in a build tree that has none, so that a fresh clone's ctest -j starts
the longest tests first, as a tree that has run ctest before does. One exception: the yardstick
golden_check.manakov_so5 (the speed of a run, .ci/run) is given 3 s, so that it starts after the
tests of more than 3 s, beside short tests of one process each, as it did in declaration order in
the runs its figures are compared with. At its own cost it would start in the first minute beside the
three compilers of student.end_to_end.correct, and read 28.4 s instead of 24.7 (2026-11-29).

Prints the number of tests and their summed seconds, the N costliest (all of them without N), and
the seconds per first part of the name (student., golden_check., engines., ...), costliest first.
CI prints the 20 costliest of each of its ctest runs this way (.ci/run)."""
import collections
import sys
import xml.etree.ElementTree as ET

YARDSTICK, YARDSTICK_COST = "golden_check.manakov_so5", 3.0


def read_cases(junit):
    """(seconds, name) of every test of a ctest JUnit file."""
    return [(float(c.get("time", 0)), c.get("name")) for c in ET.parse(junit).iter("testcase")]


def main(argv):
    if not argv:
        sys.exit(__doc__)
    if argv[0] == "--time-of":
        if len(argv) != 3:
            sys.exit(__doc__)
        times = [c.get("time", "0") for c in ET.parse(argv[2]).iter("testcase") if c.get("name") == argv[1]]
        if not times:
            return 1
        print(f"{float(times[0]):.1f}")
        return 0
    if argv[0] == "--cost-data":
        if len(argv) != 2:
            sys.exit(__doc__)
        cases = read_cases(argv[1])
        cases = [(YARDSTICK_COST if name == YARDSTICK else t, name) for t, name in cases]
        for t, name in sorted(cases, key=lambda c: (-c[0], c[1])):
            if t >= 0.5 and " " not in name:
                print(f"{name} 1 {t:.1f}")
        return 0
    cases = read_cases(argv[0])
    top = int(argv[1]) if len(argv) > 1 else len(cases)
    total = sum(t for t, _ in cases)
    print(f"  {len(cases)} tests, {total:.0f} s of test time in all")
    for t, name in sorted(cases, reverse=True)[:top]:
        print(f"  {t:7.1f} s  {name}")
    if top < len(cases):
        return 0
    groups = collections.Counter()
    for t, name in cases:
        groups[name.split(".")[0]] += t
    print("  by the first part of the name:")
    for name, t in groups.most_common():
        print(f"  {t:7.1f} s  {name}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
