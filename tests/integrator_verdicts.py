"""Every verdict true, and the same wherever it is shown (console, report.md, verdicts.json, JUnit).

    python3 integrator_verdicts.py GEOMECH SOURCE_DIR OUT_DIR

examples/integrators/verdict_cases.{hpp,cpp,py,m} hold integrators whose true behaviour is known by
theory. This test checks them with the suite and asserts, for each, the verdict theory gives:
  backward_euler           order 1 verified; bounded energy a FALSE CLAIM: it loses energy (dissipative)
  explicit_euler (+ twin)  order 1 verified; Casimir a FALSE CLAIM; the twin's verdicts identical
  always_raises            order NOT VERIFIED; every unclaimed property not established; the domain
                           check says "raises on every call"; no unclaimed row FAILS
  raises_beyond            the domain check says where it raises (|Omega| >= about 2^20) and how to
                           declare a domain; the claims its raise stopped are NOT VERIFIED
  raises_beyond_declared   the same step with its domain declared: every claim verified, the domain stated
  wrong_inside_declared    the same domain declared, explicit Euler inside it: the Casimir a FALSE CLAIM
                           (a declared domain discards only the calls outside it)
  wrong_below_raise        raises beyond 2^20 with no domain declared and takes explicit Euler below
                           |Omega| = 2^-20: the Casimir check meets the raise first, runs again inside
                           the range where the step works and finds the defect (a FALSE CLAIM)
  single_precision         detected to compute in float and judged in float: order 2 and the Casimir
                           verified (its drift is float's round-off), its 50-digit rows not run
  frame_slip               said not to reduce to the identity as h -> 0; its order claim FALSE
  lie_rk4                  order 4 FALSE, the attitude O named with its order 2
  damped_splitting         bounded energy a FALSE CLAIM: it loses energy
  still_below              said to return its input for h below about 2^-30
  capped                   said to follow 0.347 x (3.8) beyond a size
  clamped                  said to follow (3.8) shrunk to a constant size (a cap of magnitude)
  guarded_clamp            the same clamp behind a guard for h < 2^-60: the cap named, never the guard
                           for failures whose steps are above it
  rk4_casimir              Casimir a FALSE CLAIM whose cause is never "depends on the units": its
                           relative drift is the same at every scale
  float_backward_euler     bounded energy a FALSE CLAIM in single precision: it loses energy, whatever
                           the round-off noise of its plateau
  flipped_damping          bounded energy a FALSE CLAIM: its energy grows until its state is not finite,
                           said as such in C++ and through Python, never "your step raised"
  shorter_way_round        kept in a quaternion whose rotation vector takes |w|: order and equivariance
                           FALSE, caught only by the sign regime (-q given), the cause "treats q and -q
                           as two attitudes" confirmed by stepping both signs
  small_angle_snap         order and equivariance FALSE: an attitude within 1e-3 rad of the identity is
                           taken for the identity; the failures name the attitude regime near the identity
  frozen                   DOES NOT CONVERGE, and its order row FAILS
  rk4                      order 4 verified; its energy does not hold (not claimed)
  midpoint                 every claim it makes verified
Each is confirmed by a computation of this test's own (the Python steps of verdict_cases.py, and
the theory of each method), not the suite's. Then every rendering of every verdict is compared:
the console's claims block and table, report.md's table and claims, the JUnit XML, verdicts.json,
and, through a class run of the Python twins, the class summary and the gradebook. The same steps
under two names, and in C++, Python and Octave, get the same words.
"""
import csv
import importlib.util
import json
import math
import os
import re
import shutil
import struct
import subprocess
import sys
import xml.etree.ElementTree as ET

GEOMECH, SOURCE, OUT = sys.argv[1:4]
EXAMPLES = os.path.join(SOURCE, "examples", "integrators")
failures = []


def fail(what):
    failures.append(what)


def check(cond, what):
    if not cond:
        fail(what)


def run(args, timeout=1200):
    p = subprocess.run([GEOMECH] + args, capture_output=True, text=True, errors="replace", timeout=timeout)
    return p.returncode, p.stdout + p.stderr


def load(report):
    d = json.load(open(os.path.join(report, "verdicts.json")))
    decisions = {i["name"]: {c["claim"]: c for c in i["claims"]} for i in d["integrators"]}
    return d, decisions


# ---- the test's own computations (theory), on the Python steps -------------------------------

spec = importlib.util.spec_from_file_location("verdict_cases", os.path.join(EXAMPLES, "verdict_cases.py"))
cases = importlib.util.module_from_spec(spec)
spec.loader.exec_module(cases)
I0 = [1.75, 1.5, 1.25]
Pi0 = [0.65625, -0.59375, -0.1875]
O0 = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]


def backward_euler_loses_energy_at_every_step(steps=4000, h=0.25):
    x = {"Pi": Pi0, "O": O0}
    e = [cases.energy(I0, x["Pi"])]
    for _ in range(steps):
        x = cases.backward_euler_step(I0, x, h)
        e.append(cases.energy(I0, x["Pi"]))
    falls = all(b < a for a, b in zip(e, e[1:]) if abs(b - a) > 1e-15 * a)
    return falls, 1 - e[-1] / e[0]


def explicit_euler_grows_the_casimir():
    x = cases.explicit_euler_step(I0, {"Pi": Pi0, "O": O0}, 0.125)
    before = sum(p * p for p in Pi0)
    after = sum(p * p for p in x["Pi"])
    W = [p / i for p, i in zip(Pi0, I0)]
    grows_by = 0.125 ** 2 * sum(c * c for c in cases.cross(Pi0, W))  # |Pi + h Pi x W|^2 - |Pi|^2
    return after - before, grows_by


def to_float32(x):
    return struct.unpack("f", struct.pack("f", x))[0]


def float_midpoint_casimir_drift(steps=64, h=0.125):
    """The implicit midpoint rule for Pi, every value rounded to a 32-bit float, as the C++
    single_precision step computes: |Pi|^2 drifts by float's round-off, ~1e-7 relative."""
    P = [to_float32(p) for p in Pi0]
    I = [to_float32(i) for i in I0]
    c0 = sum(p * p for p in P)
    worst = 0.0
    for _ in range(steps):
        nxt = list(P)
        for _ in range(60):
            mid = [to_float32((a + b) / 2) for a, b in zip(P, nxt)]
            W = [to_float32(m / i) for m, i in zip(mid, I)]
            d = [to_float32(v) for v in cases.cross(mid, W)]
            nxt = [to_float32(p + to_float32(h * q)) for p, q in zip(P, d)]
        P = nxt
        worst = max(worst, abs(sum(p * p for p in P) - c0) / c0)
    return worst


def frame_slip_moves_by_a_fixed_amount():
    """O (O Pi) - Pi at h -> 0 for a generic O: the wrapper's slip, whatever h is."""
    a = [0.5, -1 / 3, 0.25]
    A = cases.hat(a)
    Id = cases.eye(1.0)
    # Cayley: (Id - A/2)^-1 (Id + A/2), by solving column by column (Gauss, 3x3)
    M = cases.madd(Id, A, -0.5)
    N = cases.madd(Id, A, 0.5)

    def solve(M, b):
        m = [row[:] + [bb] for row, bb in zip(M, b)]
        for i in range(3):
            p = max(range(i, 3), key=lambda r: abs(m[r][i]))
            m[i], m[p] = m[p], m[i]
            for r in range(3):
                if r != i:
                    f = m[r][i] / m[i][i]
                    m[r] = [x - f * y for x, y in zip(m[r], m[i])]
        return [m[i][3] / m[i][i] for i in range(3)]

    cols = [solve(M, [N[r][c] for r in range(3)]) for c in range(3)]
    O = [[cols[c][r] for c in range(3)] for r in range(3)]
    OP = [sum(O[i][k] * Pi0[k] for k in range(3)) for i in range(3)]
    OOP = [sum(O[i][k] * OP[k] for k in range(3)) for i in range(3)]
    return max(abs(x - y) for x, y in zip(OOP, Pi0)) / max(abs(p) for p in Pi0)


def rk4_pi_midpoint_attitude_orders():
    """lie_rk4's Pi by RK4 and O by one Cayley factor at the midpoint: the orders of each part,
    against the same method with a step 2^-4 times smaller (the error of that is far smaller)."""
    def step(x, h):
        P, O = x
        k1 = cases.euler_3_8(I0, P)
        k2 = cases.euler_3_8(I0, [p + h / 2 * k for p, k in zip(P, k1)])
        k3 = cases.euler_3_8(I0, [p + h / 2 * k for p, k in zip(P, k2)])
        k4 = cases.euler_3_8(I0, [p + h * k for p, k in zip(P, k3)])
        nxt = [p + h / 6 * (a + 2 * b + 2 * c + d) for p, a, b, c, d in zip(P, k1, k2, k3, k4)]
        W = [(p + q) / 2 / i for p, q, i in zip(P, nxt, I0)]
        A = [[h * v for v in row] for row in cases.hat(W)]
        # O cay(A) = O (Id + A/2)(Id - A/2)^-1 to second order is O exp(A) + O(h^3): a second-order
        # attitude whatever the exactness of Pi; computed here by its series to h^3.
        A2 = cases.matmul(A, A)
        cay = [[(1 if i == j else 0) + A[i][j] + A2[i][j] / 2 for j in range(3)] for i in range(3)]
        return nxt, cases.matmul(O, cay)

    def run_to(h, t=1.0):
        x = (list(Pi0), [row[:] for row in O0])
        for _ in range(int(round(t / h))):
            x = step(x, h)
        return x

    def exact_attitude_and_momentum():
        # the exact flow to t = 1 by RK4 on (Pi, O) together with h = 2^-12 (error ~1e-15)
        P, O = list(Pi0), [row[:] for row in O0]
        h = 2.0 ** -12

        def f(P, O):
            W = [p / i for p, i in zip(P, I0)]
            return cases.euler_3_8(I0, P), cases.matmul(O, cases.hat(W))
        for _ in range(2 ** 12):
            k1 = f(P, O)
            k2 = f([p + h / 2 * k for p, k in zip(P, k1[0])], cases.madd(O, k1[1], h / 2))
            k3 = f([p + h / 2 * k for p, k in zip(P, k2[0])], cases.madd(O, k2[1], h / 2))
            k4 = f([p + h * k for p, k in zip(P, k3[0])], cases.madd(O, k3[1], h))
            P = [p + h / 6 * (a + 2 * b + 2 * c + d) for p, a, b, c, d in zip(P, k1[0], k2[0], k3[0], k4[0])]
            O = [[o + h / 6 * (a + 2 * b + 2 * c + d) for o, a, b, c, d in zip(ro, r1, r2, r3, r4)]
                 for ro, r1, r2, r3, r4 in zip(O, k1[1], k2[1], k3[1], k4[1])]
        return P, O

    Pe, Oe = exact_attitude_and_momentum()
    errs = []
    for h in (1 / 8, 1 / 16):
        P, O = run_to(h)
        errs.append((max(abs(a - b) for a, b in zip(P, Pe)), max(abs(a - b) for ra, rb in zip(O, Oe) for a, b in zip(ra, rb))))
    order_O = math.log2(errs[0][1] / errs[1][1])
    order_P = math.log2(errs[0][0] / errs[1][0]) if errs[1][0] > 1e-14 else float("inf")
    return order_P, order_O


def clamped_field_sizes():
    """The clamped field of verdict_cases.hpp at Pi scaled by 2^j: its size, and its ratio to (3.8)."""
    out = []
    for j in range(0, 24, 2):
        P = [p * 2.0 ** j for p in Pi0]
        F = cases.euler_3_8(I0, P)
        n = max(abs(f) for f in F)
        G = [f * 1024.0 / n for f in F] if n > 1024 else F
        out.append((max(abs(g) for g in G), max(abs(g) for g in G) / n))
    return out


def rk4_relative_casimir_drift(scale, steps=64, h=0.125):
    """RK4 on Pi alone (the Casimir's drift does not involve O), the state scaled and h by its inverse."""
    P = [p * scale for p in Pi0]
    h = h / scale
    c0 = sum(p * p for p in P)
    for _ in range(steps):
        k1 = cases.euler_3_8(I0, P)
        k2 = cases.euler_3_8(I0, [p + h / 2 * k for p, k in zip(P, k1)])
        k3 = cases.euler_3_8(I0, [p + h / 2 * k for p, k in zip(P, k2)])
        k4 = cases.euler_3_8(I0, [p + h * k for p, k in zip(P, k3)])
        P = [p + h / 6 * (a + 2 * b + 2 * c + d) for p, a, b, c, d in zip(P, k1, k2, k3, k4)]
    return abs(sum(p * p for p in P) - c0) / c0


def flipped_damping_overflows(h=0.25, steps=100000):
    """The Python step from the long run's kind of state: the energy (sum I Omega^2 / 2) rises at every
    step until the step returns a state that is not finite, from a finite one."""
    x = {"q": [1.0, 0.0, 0.0, 0.0], "Omega": [p / i for p, i in zip(Pi0, I0)]}
    e = [sum(i * w * w for i, w in zip(I0, x["Omega"])) / 2]
    for n in range(1, steps + 1):
        y = cases.FlippedDamping.rigid_body_step(I0, x, h)
        values = y["q"] + y["Omega"]
        if not all(math.isfinite(v) for v in values):
            return n, all(math.isfinite(v) for v in x["q"] + x["Omega"]), all(b > a for a, b in zip(e, e[1:]))
        x = y
        e.append(sum(i * w * w for i, w in zip(I0, x["Omega"])) / 2)
    return None, True, False


# ---- the check of the C++ cases ----------------------------------------------------------------

shutil.rmtree(OUT, ignore_errors=True)
os.makedirs(OUT)
cpp_report = os.path.join(OUT, "cpp")
rc, console = run(["check", os.path.join(EXAMPLES, "verdict_cases.cpp"), "--report", cpp_report,
                   "--cache-dir", os.path.join(OUT, "cache")])
open(os.path.join(OUT, "console.txt"), "w").write(console)
if rc not in (0, 1):
    print(console[-5000:])
    sys.exit("the check of verdict_cases.cpp did not finish with a verdict (exit %d)" % rc)
report, dec = load(cpp_report)
verdicts = report["verdicts"]


def word(integrator, claim):
    return dec[integrator][claim]["status"]


def rows(integrator, prop=None):
    return [v for v in verdicts if v["integrator"] == integrator and (prop is None or v["property"] == prop)]


# backward Euler: dissipative.
falls, lost = backward_euler_loses_energy_at_every_step()
check(falls and lost > 0.01, "theory: backward Euler should lose energy at every step (lost %.3g)" % lost)
check(word("backward_euler", "order").startswith("verified"), "backward_euler: order 1 should be verified, is " + word("backward_euler", "order"))
check(word("backward_euler", "bounded_energy") == "FALSE CLAIM", "backward_euler: bounded energy should be a FALSE CLAIM, is " + word("backward_euler", "bounded_energy"))
check("loses energy" in dec["backward_euler"]["bounded_energy"]["measured"] and "dissipative" in dec["backward_euler"]["bounded_energy"]["measured"],
      "backward_euler: the measurement should say it loses energy (dissipative): " + dec["backward_euler"]["bounded_energy"]["measured"])

# explicit Euler and its twin.
grew, predicted = explicit_euler_grows_the_casimir()
check(abs(grew - predicted) <= 1e-12 * max(1.0, predicted) and grew > 0, "theory: explicit Euler grows |Pi|^2 by h^2 |Pi x W|^2")
check(word("explicit_euler", "casimir") == "FALSE CLAIM", "explicit_euler: the Casimir claim should be FALSE")
check(word("explicit_euler", "order").startswith("verified"), "explicit_euler: order 1 should be verified")
for claim in dec["explicit_euler"]:
    a, b = dec["explicit_euler"][claim], dec["explicit_euler_twin"][claim]
    check((a["status"], a["measured"]) == (b["status"], b["measured"]),
          "twins differ on %s: %s / %s against %s / %s" % (claim, a["status"], a["measured"], b["status"], b["measured"]))
for v in rows("explicit_euler"):
    twin = [w for w in rows("explicit_euler_twin", v["property"]) if w["scalar"] == v["scalar"]]
    check(twin and twin[0]["outcome"] == v["outcome"] and twin[0].get("word") == v.get("word"),
          "twins' rows differ: %s [%s]" % (v["property"], v["scalar"]))

# A step that raises on every call.
try:
    cases.AlwaysRaises.rigid_body_step(I0, {"Pi": Pi0, "O": O0}, 0.1)
    fail("theory: the Python always_raises should raise")
except RuntimeError:
    pass
check(word("always_raises", "order") == "NOT VERIFIED", "always_raises: order should be NOT VERIFIED, is " + word("always_raises", "order"))
for claim, d in dec["always_raises"].items():
    if d["claimed"] == "no" and claim != "order":
        check(d["status"].startswith("not established") or d["status"] == "-",
              "always_raises: unclaimed %s should be not established, is %s" % (claim, d["status"]))
for v in rows("always_raises"):
    prop_claimed = v["property"] in ("integrator_order", "integrator_local_order", "integrator_converges_in_every_regime",
                                     "integrator_50_digit_floor", "integrator_domain", "integrator_small_turns")
    if not prop_claimed:
        check(v["outcome"] == "NOT CHARACTERISED", "always_raises: unclaimed %s [%s] should be NOT CHARACTERISED, is %s"
              % (v["property"], v["scalar"], v["outcome"]))
domain = [v for v in rows("always_raises", "integrator_domain")]
check(domain and all(v["outcome"] == "FAIL" and "raises on every call" in v["message"] for v in domain),
      "always_raises: the domain check should say it raises on every call")

# An engine refusing fast states, without and with a declared domain.
threshold = 2 ** 20  # verdict_cases.hpp: refuse_fast
dom = rows("raises_beyond", "integrator_domain")
m = re.search(r"raises for max \|Omega_i\| >= ([0-9.e+]+)", dom[0]["message"]) if dom else None
check(m is not None and threshold <= float(m.group(1)) <= 2 * threshold,
      "raises_beyond: the domain check should place the raise at |Omega| >= 2^20 (within a factor 2): %s" % (dom[0]["message"][:300] if dom else "no row"))
check(dom and "declare its domain" in dom[0]["message"], "raises_beyond: the domain check should say a domain may be declared")
for claim in ("casimir", "energy"):
    check(word("raises_beyond", claim) == "NOT VERIFIED", "raises_beyond: %s should be NOT VERIFIED, is %s" % (claim, word("raises_beyond", claim)))
for claim in ("order", "casimir", "energy", "orthogonality"):
    check(word("raises_beyond_declared", claim).startswith("verified"),
          "raises_beyond_declared: %s should be verified inside its domain, is %s" % (claim, word("raises_beyond_declared", claim)))
check(all(v["outcome"] == "PASS" for v in rows("raises_beyond_declared", "integrator_domain")), "raises_beyond_declared: the domain check should pass")
check("declared domain: |Omega| <= 5.24e+05" in console, "the console should state the declared domain")
# The negative control of a domain: a step wrong inside the domain it declares is still caught.
check(word("wrong_inside_declared", "casimir") == "FALSE CLAIM",
      "wrong_inside_declared: a Casimir broken inside the declared domain should be a FALSE CLAIM, is " + word("wrong_inside_declared", "casimir"))
check(word("wrong_inside_declared", "order").startswith("verified"),
      "wrong_inside_declared: order 1 (explicit Euler) should be verified, is " + word("wrong_inside_declared", "order"))

# A defect below a raise: the check run again inside the range where the step works finds it.
check(word("wrong_below_raise", "casimir") == "FALSE CLAIM",
      "wrong_below_raise: the Casimir should be a FALSE CLAIM, is " + word("wrong_below_raise", "casimir"))
# Which the check meets first, the raise or the defect, depends on the draws; met after the raise,
# the defect must be found by the run inside the working range and said so.
for m in [v["message"] for v in rows("wrong_below_raise") if v["outcome"] == "FAIL" and v["property"] != "integrator_domain"]:
    if m.startswith("your step raised"):
        check(("run again inside" in m and "the check fails there too" in m)
              or "in the cases where it did not raise the check fails too" in m,
              "wrong_below_raise: a failure met after a raise should be found inside the working range: " + m[:400])
grew, _ = explicit_euler_grows_the_casimir()
check(grew > 0, "theory: explicit Euler, the step below 2^-20, grows the Casimir")

# Single precision, not stated: detected, and judged at float's precision. The midpoint rule keeps
# |Pi|^2 to float's round-off (theory), so in float its claims hold: order 2 and the Casimir verified,
# the verdicts naming float and how it was found, the 50-digit rows saying why they do not run.
FLT_EPSILON = 2.0 ** -23
drift = float_midpoint_casimir_drift()
check(1e-9 < drift < 64 * FLT_EPSILON, "theory: the float midpoint should drift |Pi|^2 by float round-off, drifted %.3g" % drift)
single = [i for i in report["integrators"] if i["name"] == "single_precision"]
judged = single[0].get("precision", {}).get("judged", {}) if single else {}
check(judged.get("name") == "float" and judged.get("how", "").startswith("detected"),
      "single_precision: should be detected to compute in float: %s" % judged)
check(word("single_precision", "order").startswith("verified") and word("single_precision", "casimir").startswith("verified"),
      "single_precision: order and Casimir claims should be verified in float, are %s, %s"
      % (word("single_precision", "order"), word("single_precision", "casimir")))
check("float eps" in dec["single_precision"]["casimir"]["measured"],
      "single_precision: the Casimir residual should be measured in float eps: " + dec["single_precision"]["casimir"]["measured"])
mp = [v for v in rows("single_precision") if v["scalar"] == "mp50"]
check(mp and all(v["outcome"] == "NOT PROVIDED" and "computes in float" in v["message"] for v in mp),
      "single_precision: its 50-digit rows should say the step computes in float: %s" % (mp[0]["message"][:200] if mp else "no row"))
sp = [v for v in rows("single_precision") if v["outcome"] == "FAIL"]
check(all("your step follows dPi/dt" not in v["message"] for v in sp), "single_precision: no vector field made of round-off may be shown")

# A frame-conversion slip.
moved = frame_slip_moves_by_a_fixed_amount()
check(moved > 1e-3, "theory: O O Pi differs from Pi by a fixed amount (%.3g)" % moved)
fs = [v for v in rows("frame_slip") if v["outcome"] == "FAIL"]
check(fs and any("does not reduce to the identity" in v["message"] for v in fs), "frame_slip: should be told it does not reduce to the identity")
check(word("frame_slip", "order") == "FALSE CLAIM", "frame_slip: order 2 should be FALSE")

# A Lie-group RK4 whose attitude is order 2.
order_P, order_O = rk4_pi_midpoint_attitude_orders()
check(abs(order_O - 2) < 0.3 and order_P > 3.5, "theory: lie_rk4's O should be order 2 and Pi order 4 (%.2f, %.2f)" % (order_O, order_P))
check(word("lie_rk4", "order") == "FALSE CLAIM", "lie_rk4: order 4 should be FALSE")
lo = rows("lie_rk4", "integrator_order")
check(lo and all(re.search(r"O: order 2\.0", v["message"]) for v in lo if v["outcome"] == "FAIL"),
      "lie_rk4: the order failure should name O with order 2: " + (lo[0]["message"][:300] if lo else ""))

# A damped splitting.
check(word("damped_splitting", "bounded_energy") == "FALSE CLAIM" and "loses energy" in dec["damped_splitting"]["bounded_energy"]["measured"],
      "damped_splitting: bounded energy should be a FALSE CLAIM, losing energy")

# A step that does nothing below some h.
sb = [v["message"] for v in rows("still_below") if v["outcome"] == "FAIL"]
m = [re.search(r"returns its input unchanged for h <= ([0-9.e+-]+) \(it moves x at h = ([0-9.e+-]+)", s) for s in sb]
m = [x for x in m if x]
check(m and all(float(x.group(1)) < 2 ** -30 <= float(x.group(2)) for x in m),
      "still_below: should be told it returns its input below h = 2^-30: " + (sb[0][:300] if sb else "no failure"))

# A capped field.
cp = [v["message"] for v in rows("capped") if v["outcome"] == "FAIL"]
check(cp and any("0.347 x (3.8)" in s for s in cp), "capped: should be told its field is 0.347 x (3.8) beyond a size")

# A field clamped to a constant size (the "capped in magnitude"): the cap, confirmed at the
# failing state, is what is named.
sizes = clamped_field_sizes()
clamped_at = [r for size, r in sizes if r < 1]
check(clamped_at and all(abs(size - 1024.0) < 1e-9 for size, r in sizes if r < 1) and len(set(round(r, 12) for r in clamped_at)) > 1,
      "theory: the clamped field should have the constant size 1024 beyond the clamp, at varying fractions of (3.8)")
for name in ("clamped", "guarded_clamp"):
    msgs = [v["message"] for v in rows(name) if v["outcome"] == "FAIL"]
    check(any("shrunk to the constant size max |dPi_i/dt| = 1024" in m for m in msgs),
          "%s: should be told its field is (3.8) shrunk to the constant size 1024: %s" % (name, msgs[0][:400] if msgs else "no failure"))
# The guard of guarded_clamp (h < 2^-60) is named only where the failing steps lie below it.
for m in (v["message"] for v in rows("guarded_clamp") if v["outcome"] == "FAIL"):
    for g in re.finditer(r"returns its input unchanged for h <= [0-9.e+-]+ .*?(not the cause here|steps down to h = ([0-9.e+-]+))", m):
        check(g.group(1) == "not the cause here" or float(g.group(2)) < 2.0 ** -60,
              "guarded_clamp: the guard named as the cause for steps above it: " + g.group(0)[:300])

# RK4's Casimir drift: the same relative drift at every scale (bit for bit: scaling by powers of 2 is
# exact), so the units are never its cause.
drifts = [rk4_relative_casimir_drift(2.0 ** k) for k in (-20, 0, 12)]
check(drifts[0] == drifts[1] == drifts[2] and drifts[1] > 0, "theory: RK4's relative Casimir drift should not depend on the scale: %r" % drifts)
check(word("rk4_casimir", "casimir") == "FALSE CLAIM", "rk4_casimir: the Casimir claim should be FALSE, is " + word("rk4_casimir", "casimir"))
check(word("rk4_casimir", "order").startswith("verified"), "rk4_casimir: order 4 should be verified")
said = " ".join([v["message"] for v in rows("rk4_casimir")] + [dec["rk4_casimir"]["casimir"].get("why", ""),
                                                                 dec["rk4_casimir"]["casimir"]["measured"], dec["rk4_casimir"]["casimir"].get("evidence", "")])
check("depends on the units" not in said, "rk4_casimir: the units named as the cause of a covariant drift: " + said[:600])

# Backward Euler in single precision: a loss, told apart from an oscillation despite float noise.
check(word("float_backward_euler", "bounded_energy") == "FALSE CLAIM",
      "float_backward_euler: bounded energy should be a FALSE CLAIM, is " + word("float_backward_euler", "bounded_energy"))
check("loses energy" in dec["float_backward_euler"]["bounded_energy"]["measured"],
      "float_backward_euler: the measurement should say it loses energy: " + dec["float_backward_euler"]["bounded_energy"]["measured"])

# An attitude snapped to the identity within 1e-3 rad: the attitude regimes find it and say so.
def snapped(theta):
    """Whether small_angle_snap takes an attitude theta rad about x from the identity for the identity."""
    O = [[1, 0, 0], [0, math.cos(theta), -math.sin(theta)], [0, math.sin(theta), math.cos(theta)]]
    sin2 = ((O[2][1] - O[1][2]) ** 2 + (O[0][2] - O[2][0]) ** 2 + (O[1][0] - O[0][1]) ** 2) / 4
    return O[0][0] + O[1][1] + O[2][2] > 1 and sin2 < 1e-6


check(snapped(2.0 ** -12) and snapped(2.0 ** -40) and not snapped(2.0 ** -6) and not snapped(math.pi - 2.0 ** -12),
      "theory: the snap acts within 1e-3 rad of the identity, and only there")
for claim in ("order", "equivariant"):
    check(word("small_angle_snap", claim) == "FALSE CLAIM",
          "small_angle_snap: %s should be a FALSE CLAIM, is %s" % (claim, word("small_angle_snap", claim)))
named = [v for v in rows("small_angle_snap") if v["outcome"] == "FAIL" and
         any(c["type"].startswith("attitude (0, 1 generic") and c["value"].strip() == "2" for c in v.get("counterexample", []))]
check(named, "small_angle_snap: a failure should name its attitude regime (2: 2^-m rad from the identity): " +
      "; ".join("%s %r" % (v["property"], [c["type"] for c in v.get("counterexample", [])][:4])
                for v in rows("small_angle_snap") if v["outcome"] == "FAIL")[:800])
eq = [v for v in rows("small_angle_snap", "integrator_equivariant") if v["outcome"] == "FAIL"]
check(eq, "small_angle_snap: equivariance should FAIL (it held on random attitudes before the regimes)")

# An engine's step whose damping grows Omega until its state is not finite: a measurement, not a raise.
blown_at, from_finite, rising = flipped_damping_overflows()
check(blown_at is not None and from_finite and rising,
      "theory: flipped_damping should grow its energy at every step until a step returns a non-finite state "
      "from a finite one (%r, %r, %r)" % (blown_at, from_finite, rising))


def says_not_finite_never_raised(d, rows_of, where):
    check(d["flipped_damping"]["bounded_energy"]["status"] == "FALSE CLAIM" and
          "H is not finite" in d["flipped_damping"]["bounded_energy"]["measured"],
          "%s flipped_damping: bounded energy should be a FALSE CLAIM whose energy is not finite: %s / %s"
          % (where, d["flipped_damping"]["bounded_energy"]["status"], d["flipped_damping"]["bounded_energy"]["measured"]))
    told = " ".join(v["message"] for v in rows_of) + " ".join(c.get("measured", "") + c.get("why", "")
                                                             for c in d["flipped_damping"].values())
    check("raise" not in told, "%s flipped_damping: a non-finite state called a raise: %s" % (where, told[:600]))


says_not_finite_never_raised(dec, rows("flipped_damping"), "C++")

# A quaternion's sign assumed: (|w|, v) is the attitude of q only when w >= 0.
def rotation_of(q):
    w, x, y, z = q
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]


def shorter_way_round_moves(q):
    used = [abs(q[0])] + list(q[1:])
    return max(abs(a - b) for ra, rb in zip(rotation_of(q), rotation_of(used)) for a, b in zip(ra, rb))


near_identity = [math.cos(2.0 ** -7), math.sin(2.0 ** -7), 0.0, 0.0]
check(shorter_way_round_moves(near_identity) == 0 and shorter_way_round_moves([-c for c in near_identity]) > 1e-3,
      "theory: taking |w| keeps the attitude of q with w >= 0 and turns it for -q")
for claim in ("order", "equivariant"):
    check(word("shorter_way_round", claim) == "FALSE CLAIM",
          "shorter_way_round: %s should be a FALSE CLAIM, is %s" % (claim, word("shorter_way_round", claim)))
sw = [v for v in rows("shorter_way_round") if v["outcome"] == "FAIL" and v["scalar"] == "double"]
check(any(any(c["type"].startswith("sign of the quaternion") and c["value"].strip() == "1" for c in v.get("counterexample", []))
          for v in sw), "shorter_way_round: a failure should name the sign regime (-q given)")
check(any("treats q and -q as two attitudes" in v["message"] for v in sw),
      "shorter_way_round: the cause should be the sign, by experiment: " + (sw[0]["message"][:400] if sw else "no failure"))

# A step that does nothing.
check(word("frozen", "order") == "DOES NOT CONVERGE", "frozen: order should be DOES NOT CONVERGE, is " + word("frozen", "order"))
check(any(v["outcome"] == "FAIL" for v in rows("frozen", "integrator_order")), "frozen: its order row should FAIL (it asserts convergence)")
check(any("leaves Pi unchanged" in v["message"] for v in rows("frozen") if v["outcome"] == "FAIL"), "frozen: should be told it leaves Pi unchanged")

# RK4 and the midpoint rule.
check(word("rk4", "order").startswith("verified"), "rk4: order 4 should be verified")
check(word("rk4", "energy").startswith("does not hold"), "rk4: its energy should not hold")
for claim, d in dec["midpoint"].items():
    if d["claimed"] != "no":
        check(d["status"].startswith("verified"), "midpoint: %s should be verified, is %s" % (claim, d["status"]))

# ---- every rendering of every verdict --------------------------------------------------------

md = open(os.path.join(cpp_report, "report.md"), encoding="utf-8").read()
junit = ET.parse(os.path.join(cpp_report, "junit.xml"))
junit_words = {}
for case in junit.iter("testcase"):
    for prop in case.iter("property"):
        if prop.get("name") == "verdict":
            junit_words[(case.get("classname").rsplit(".", 1)[1], case.get("name"))] = prop.get("value")


def md_unescape(s):
    return s.replace("\\|", "|").replace("&lt;", "<").replace("&gt;", ">").replace("&amp;", "&")


for integ, claims in dec.items():
    # "integrator 'X' claims:", with the declared state form and precision between when there are
    block = re.search(r"^integrator '%s'[^\n]* claims[^\n]*:\n(.*?)\n\n" % re.escape(integ), console, re.S | re.M)
    check(block is not None, "the console has no claims block for " + integ)
    table = re.search(r"### %s\n(.*?)(\n### |\n## )" % re.escape(integ), md, re.S)
    check(table is not None, "report.md has no claims section for " + integ)
    for claim, d in claims.items():
        if d["status"] == "-":
            continue
        if block:
            line = re.search(r"^  %s\s+%s\s+(.*)$" % (re.escape(claim), re.escape(d["claimed"])), block.group(1), re.M)
            check(line and line.group(1).startswith(d["status"]),
                  "%s %s: console says %r, verdicts.json %r" % (integ, claim, line.group(1) if line else None, d["status"]))
        if table:
            row = re.search(r"^\| %s \| %s \| \**(.*?)\** \|" % (re.escape(claim), re.escape(d["claimed"])), table.group(1), re.M)
            check(row and md_unescape(row.group(1)) == d["status"],
                  "%s %s: report.md says %r, verdicts.json %r" % (integ, claim, row.group(1) if row else None, d["status"]))
seen_shown = {}
for v in verdicts:
    if not v["integrator"] or v["outcome"] == "NOT PROVIDED":
        continue
    w = v.get("word", v["outcome"])
    name = "%s [%s]" % (v["property"], v["integrator"])
    check(junit_words.get((v["scalar"], name)) == w, "%s [%s]: JUnit says %r, verdicts.json %r" % (name, v["scalar"], junit_words.get((v["scalar"], name)), w))
    shown = name  # the console's column of names: 43 characters, the integrator kept whole
    if len(name) > 43:
        b = name.rfind(" [")
        shown = name[:43 - (len(name) - b) - 1] + "~" + name[b:] if b >= 0 and len(name) - b <= 34 else name[:42] + "~"
    check(seen_shown.get(shown, name) == name, "%s: the console shows it under the same name as %s" % (name, seen_shown.get(shown)))
    seen_shown.setdefault(shown, name)
    cell = re.search(r"^%s\s.*$" % re.escape(shown), console, re.M)
    check(cell and w in cell.group(0), "%s: the console's table row does not show %r" % (name, w))
    mdrow = re.search(r"^\| `%s` \|.*$" % re.escape(name), md, re.M)
    check(mdrow and (w in md_unescape(mdrow.group(0))), "%s: report.md's row does not show %r" % (name, w))

# ---- the same steps in Python and Octave, and in a class -------------------------------------

narrow = ["--scalar", "double", "-p", "integrator_order", "-p", "integrator_casimir", "-p", "integrator_domain"]
by_language = {"c++": dec}
for lang, f in (("python", "verdict_cases.py"), ("octave", "verdict_cases.m")):
    r = os.path.join(OUT, lang)
    rc, text = run(["check", os.path.join(EXAMPLES, f), "--report", r] + narrow)
    if rc not in (0, 1):
        fail("%s: the check did not finish (exit %d): %s" % (lang, rc, text[-2000:]))
        continue
    _, d = load(r)
    by_language[lang] = d
    for claim in d["explicit_euler"]:
        a, b = d["explicit_euler"][claim], d["explicit_euler_twin"][claim]
        check((a["status"], a["measured"]) == (b["status"], b["measured"]), "%s twins differ on %s" % (lang, claim))
    check(d["explicit_euler"]["casimir"]["status"] == "FALSE CLAIM", "%s explicit_euler: Casimir should be FALSE" % lang)
    check(d["explicit_euler"]["order"]["status"].startswith("verified"), "%s explicit_euler: order should be verified" % lang)
    check("raises for max |Omega_i| >=" in " ".join(v["message"] for v in load(r)[0]["verdicts"]
                                               if v["integrator"] == "raises_beyond" and v["property"] == "integrator_domain"),
          "%s raises_beyond: the domain check should say where it raises" % lang)
    check(d["raises_beyond_declared"]["order"]["status"].startswith("verified"), "%s raises_beyond_declared: order should be verified" % lang)

# The same engine through Python: its NaN crosses the protocol as what the step computed.
r = os.path.join(OUT, "python-flipped")
rc, text = run(["check", os.path.join(EXAMPLES, "verdict_cases.py"), "--report", r, "--integrator", "flipped_damping",
                "--scalar", "double", "-p", "integrator_bounded_energy", "-p", "integrator_domain"])
if rc not in (0, 1):
    fail("python flipped_damping: the check did not finish (exit %d): %s" % (rc, text[-2000:]))
else:
    report_py, d = load(r)
    says_not_finite_never_raised(d, [v for v in report_py["verdicts"] if v["integrator"] == "flipped_damping"], "python")

# A class of the Python cases: the class summary and the gradebook render the same decisions.
klass = os.path.join(OUT, "class")
os.makedirs(klass)
shutil.copy(os.path.join(EXAMPLES, "verdict_cases.py"), os.path.join(klass, "cases.py"))
rubric = os.path.join(OUT, "rubric.json")
json.dump({"claims_weight": 1, "slots": {"default": 0}, "assignment": ["hat"]}, open(rubric, "w"))
rc, text = run(["check-class", klass, "--report", os.path.join(OUT, "class-report"), "--grades", os.path.join(OUT, "grades.csv"),
                "--rubric", rubric, "--parallel", "1"] + narrow)
if rc not in (0, 1):
    fail("the class run did not finish (exit %d): %s" % (rc, text[-2000:]))
else:
    _, cd = load(os.path.join(OUT, "class-report", "cases"))
    summary = open(os.path.join(OUT, "class-report", "summary.md"), encoding="utf-8").read()
    # A claim none of whose checks the lecturer selected (-p) has no evidence either way: the class
    # leaves it out, as a claim not made (docs/GRADEBOOK.md); every other claim made is counted.
    made = [(i, c, d["status"]) for i, cs in cd.items() for c, d in cs.items()
            if d["claimed"] != "no" and "not selected in this run" not in d["status"]]
    verified = [x for x in made if x[2].startswith("verified")]
    check(("claims: %d of %d verified" % (len(verified), len(made))) in summary,
          "the class summary's claims count differs from the report's (%d of %d verified):\n%s" % (len(verified), len(made), summary[-1500:]))
    for i, c, s in made:
        if not s.startswith("verified"):
            check(("%s %s (%s)" % (i, c, s)) in summary, "the class summary does not say %s %s is %s" % (i, c, s))
    book = list(csv.reader(open(os.path.join(OUT, "grades.csv"), encoding="utf-8")))
    expected = round(100.0 * len(verified) / len(made), 2)
    got = float(book[1][4]) if len(book) > 1 else None
    check(got is not None and abs(got - expected) < 0.01, "the gradebook's grade %s should be %.2f (the share of verified claims)" % (got, expected))

if failures:
    print("\n".join("FAILED: " + f for f in failures))
    sys.exit(1)
print("every integrator's verdict is the one theory gives, and every rendering shows the same")
