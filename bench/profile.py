#!/usr/bin/env python3
"""Where a check's time goes (docs/PERFORMANCE.md), read from the verdicts.json of its report:

    ./geomech check examples/students/correct.py --report /tmp/r && bench/profile.py /tmp/r/verdicts.json [N]

Per property (its scalars and integrators together), the N costliest (default 20) by wall seconds:
  wall      the seconds its checks ran (in a process of their own, one per worker at a time);
  calls     the slot calls it made of an implementation behind the protocol (Python, Octave, a
            sandboxed C++ file); 0 for a C++ file linked in;
  trips     the round trips those took (a call answered from the suite's memory takes none);
  memo      the calls answered from memory;
  waiting   the wall seconds spent waiting for replies: the implementation's compute, its encoding
            and the pipe;
  code cpu  the CPU seconds of the implementation's server (0 in process: counted in suite cpu);
  suite cpu the CPU seconds of the suite's own process: generating, comparing, encoding requests.
Then the totals, and the share of the wall the waiting takes."""
import collections
import json
import sys


def main(argv):
    if not argv:
        sys.exit(__doc__)
    report = json.load(open(argv[0]))
    top = int(argv[1]) if len(argv) > 1 else 20
    keys = ("wall", "calls", "trips", "memo", "waiting", "code", "suite")
    per = collections.defaultdict(lambda: dict.fromkeys(keys, 0.0))
    for v in report["verdicts"]:
        f = v.get("profile", {})
        row = per[v["property"]]
        row["wall"] += v.get("seconds", 0)
        row["calls"] += f.get("calls", 0)
        row["trips"] += f.get("round_trips", 0)
        row["memo"] += f.get("memo_hits", 0)
        row["waiting"] += f.get("waiting_seconds", 0)
        row["code"] += f.get("code_cpu_seconds", 0)
        row["suite"] += f.get("suite_cpu_seconds", 0)
    total = dict.fromkeys(keys, 0.0)
    for row in per.values():
        for k in keys:
            total[k] += row[k]
    print(f"{report.get('source', '?')}: {report.get('language', '?')}, {len(report['verdicts'])} verdicts of "
          f"{len(per)} properties, the whole check {report.get('seconds', 0):.1f} s of wall")
    print(f"{'property':<48} {'wall s':>7} {'calls':>8} {'trips':>8} {'memo':>7} {'waiting s':>9} {'code cpu':>8} {'suite cpu':>9}")
    for name, r in sorted(per.items(), key=lambda kv: -kv[1]["wall"])[:top]:
        print(f"{name[:48]:<48} {r['wall']:7.2f} {int(r['calls']):8d} {int(r['trips']):8d} {int(r['memo']):7d} "
              f"{r['waiting']:9.2f} {r['code']:8.2f} {r['suite']:9.2f}")
    t = total
    print(f"{'all ' + str(len(per)) + ' properties':<48} {t['wall']:7.2f} {int(t['calls']):8d} {int(t['trips']):8d} "
          f"{int(t['memo']):7d} {t['waiting']:9.2f} {t['code']:8.2f} {t['suite']:9.2f}")
    if t["wall"] > 0:
        per_trip = 1e6 * t["waiting"] / t["trips"] if t["trips"] else 0
        print(f"waiting for replies: {100 * t['waiting'] / t['wall']:.0f}% of the checks' wall"
              + (f", {per_trip:.0f} us a round trip" if t["trips"] else "")
              + (f"; {100 * t['memo'] / t['calls']:.0f}% of the calls answered from memory" if t["calls"] else ""))


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
