"""One cause per failure, confirmed or "cause not identified" (examples/integrators/cause_cases.*).

    python3 cause_verdicts.py GEOMECH SOURCE_DIR OUT_DIR

Each integrator of cause_cases.hpp has one known defect. This test checks them and asserts, for each,
the verdict and the one cause its failures may name, each confirmed by a computation of its own:
  small_angle_series           order FALSE; where a regime names a cause it is the attitude's angle (this
                               test: turned in space, the same case converges), never the special state
  ignores_negative_h           symmetric FALSE, said to do nothing for h < 0 (this test: step(-h) returns x)
  speed_cap                    Casimir FALSE, the cap on the turn of one step named with its angle
                               (this test: |Pi| after a step of h |Omega| = 2 is pi/4 / 2 of |Pi|)
  raises_slow_wrong_elsewhere  order FALSE (its checks ran and failed), whatever the raise stopped
  no_gyroscopic                order FALSE, the field dPi/dt = 0 named, never a wrong h nor "cause not
                               identified"
and no message names a second cause after a confirmed one, nor generic advice beside one.
"""
import importlib.util
import json
import math
import os
import shutil
import subprocess
import sys

GEOMECH, SOURCE, OUT = sys.argv[1:4]
EXAMPLES = os.path.join(SOURCE, "examples", "integrators")
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)


spec = importlib.util.spec_from_file_location("verdict_cases", os.path.join(EXAMPLES, "verdict_cases.py"))
cases = importlib.util.module_from_spec(spec)
spec.loader.exec_module(cases)

I0 = [1.75, 1.5, 1.25]
P0 = [0.65625, -0.59375, -0.1875]


def midpoint(I, P, h):
    nxt = list(P)
    for _ in range(200):
        mid = [(a + b) / 2 for a, b in zip(P, nxt)]
        again = [p + h * f for p, f in zip(P, cases.euler_3_8(I, mid))]
        done = max(abs(a - b) for a, b in zip(again, nxt)) <= 8 * 2.0 ** -52 * max(abs(p) for p in P)
        nxt = again
        if done:
            break
    return nxt


def speed_cap_ratio(turn):
    """|Pi| after one step of the capped midpoint at |Omega h| = turn, over |Pi|."""
    W = [p / i for p, i in zip(P0, I0)]
    speed = math.sqrt(sum(w * w for w in W))
    h = turn / speed
    P = [p * (math.pi / 4) / turn for p in P0] if turn > math.pi / 4 else list(P0)
    Q = midpoint(I0, P, h)
    return math.sqrt(sum(q * q for q in Q)) / math.sqrt(sum(p * p for p in P0))


shutil.rmtree(OUT, ignore_errors=True)
os.makedirs(OUT)
report = os.path.join(OUT, "report")
p = subprocess.run([GEOMECH, "check", os.path.join(EXAMPLES, "cause_cases.cpp"), "--scalar", "double", "--report",
                    report], capture_output=True, text=True, errors="replace", timeout=1200)
out = p.stdout + p.stderr
open(os.path.join(OUT, "check.txt"), "w").write(out)
check(p.returncode == 1, "the check should exit 1 (false claims), got %d" % p.returncode)
d = json.load(open(os.path.join(report, "verdicts.json")))
dec = {i["name"]: {c["claim"]: c for c in i["claims"]} for i in d["integrators"]}
fails = {}
for v in d["verdicts"]:
    if v.get("integrator") and v["outcome"] == "FAIL":
        fails.setdefault(v["integrator"], []).append(v)


def status(integ, claim):
    return dec.get(integ, {}).get(claim, {}).get("status", "")


# Nowhere a second cause after a confirmed one, nor advice beside a confirmed cause.
confirmed = ("cause, by experiment", "your step leaves Pi unchanged", "a cap", "your step returns its input",
             "your step follows dPi/dt")
for integ, vs in fails.items():
    for v in vs:
        m = v["message"]
        n = sum(m.count(c) for c in ("cause, by experiment", "a cap, by experiment", "a cap on the turn"))
        check(n <= 1, "%s [%s]: more than one cause named:\n%s" % (v["property"], integ, m))
        if any(c in m for c in confirmed):
            check("what to look for" not in m and "cause not identified" not in m,
                  "%s [%s]: advice or 'cause not identified' beside a confirmed cause:\n%s" % (v["property"], integ, m))

# 1. The small-angle series: the attitude's angle, never the special state.
check(status("small_angle_series", "order").startswith("FALSE CLAIM"), "small_angle_series: order FALSE CLAIM")
for v in fails.get("small_angle_series", []):
    check("branches at this special state" not in v["message"],
          "small_angle_series [%s]: blamed on a special state:\n%s" % (v["property"], v["message"]))
named = [v for v in fails.get("small_angle_series", []) if "cause, by experiment" in v["message"]]
check(all("the attitude's own angle" in v["message"] for v in named),
      "small_angle_series: a cause named must be the attitude's angle")

# 2. A step that does nothing for h < 0.
x1 = {"Pi": midpoint(I0, P0, 0.25), "O": cases.eye(1.0)}
check(x1["Pi"] != P0, "this test: the step moves x at h = 1/4")
check(status("ignores_negative_h", "symmetric").startswith("FALSE CLAIM"), "ignores_negative_h: symmetric FALSE CLAIM")
check(any("your step returns its input for h < 0" in v["message"] for v in fails.get("ignores_negative_h", [])),
      "ignores_negative_h: the failure should say the step does nothing for h < 0")

# 3. The speed cap: the turn of one step, with its angle.
r2 = speed_cap_ratio(2.0)
check(abs(r2 - math.pi / 8) < 1e-9, "this test: the cap leaves pi/8 of |Pi| at a turn of 2 rad (%r)" % r2)
check(status("speed_cap", "casimir").startswith("FALSE CLAIM"), "speed_cap: Casimir FALSE CLAIM")
check(any("a cap on the turn of one step" in v["message"] and "0.7854 rad" in v["message"]
          for v in fails.get("speed_cap", [])), "speed_cap: the cap on the turn of one step should be named, 0.7854 rad")
check(status("speed_cap", "order").startswith("verified"), "speed_cap: order verified (a cap at large steps only)")

# 4. Raises in one regime, wrong elsewhere: FALSE CLAIM.
check(status("raises_slow_wrong_elsewhere", "order").startswith("FALSE CLAIM"),
      "raises_slow_wrong_elsewhere: order should be a FALSE CLAIM, is '%s'" % status("raises_slow_wrong_elsewhere",
                                                                                    "order"))

# 5. No gyroscopic term: the field.
check(status("no_gyroscopic", "order").startswith("FALSE CLAIM"), "no_gyroscopic: order FALSE CLAIM")
for v in fails.get("no_gyroscopic", []):
    check("your step leaves Pi unchanged (dPi/dt = 0)" in v["message"],
          "no_gyroscopic [%s]: the field should be named" % v["property"])
    check("slightly wrong h" not in v["message"] and "cause not identified" not in v["message"],
          "no_gyroscopic [%s]: no other cause beside the field" % v["property"])

for f in failures:
    print("FAIL:", f)
print("%d failures" % len(failures))
sys.exit(1 if failures else 0)
