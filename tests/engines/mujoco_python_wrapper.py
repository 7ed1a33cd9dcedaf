"""A wrapper whose engine lives in another runtime: MuJoCo driven from Python through a Node server
beside it (examples/engines/mujoco_through_python.py, naming its own files with `# geomech: beside`),
checked trusted and untrusted. Behind the sandbox the wrapper's files are shown with it and the npm
package from a folder the grader trusts; the verdicts must be the trusted ones, claim by claim, and
MuJoCo's (RK4's documented order 4 false at 2.00, Euler's 1 verified). Then the control of the
machine's side: a stand-in Node that cannot start inside the sandbox is the grader's machine (exit 3,
its fix named), for the JavaScript file itself and for the Python wrapper that needs Node, never the
code's FAIL.

    python3 mujoco_python_wrapper.py GEOMECH PROJECT_DIR OUT_DIR
"""
import json
import os
import shutil
import stat
import subprocess
import sys

geomech, project, out = sys.argv[1:4]
engines = os.path.join(project, "examples", "engines")
wrapper = os.path.join(engines, "mujoco_through_python.py")
failures = []


def check(name, file, *extra, env=None):
    report = os.path.join(out, name)
    e = dict(os.environ)
    e.setdefault("GEOMECH_PYTHON", "/usr/bin/python3")  # the system's, which the sandbox can read
    e["GEOMECH_LIBRARY_ROOTS"] = engines
    e.update(env or {})
    r = subprocess.run([geomech, "check", file, "--scalar", "double", "-p", "integrator_order", "--quiet",
                        "--report", report, *extra], env=e, capture_output=True, text=True)
    return r, report


def claims(report):
    with open(os.path.join(report, "verdicts.json")) as f:
        j = json.load(f)
    return {(i["name"], c["claim"]): (c["status"], c["measured"]) for i in j["integrators"] for c in i["claims"]}


shutil.rmtree(out, ignore_errors=True)
os.makedirs(out)
found = {}
for mode, extra in (("trusted", ()), ("untrusted", ("--untrusted",))):
    r, report = check(mode, wrapper, *extra)
    print("%s: exit %d\n%s" % (mode, r.returncode, r.stderr[-2000:]))
    if r.returncode != 1:
        failures.append("%s: exit %d, expected 1 (RK4's documented order 4 is false)" % (mode, r.returncode))
        continue
    found[mode] = claims(report)
    rk4 = found[mode].get(("mujoco_rk4", "order"))
    euler = found[mode].get(("mujoco_euler", "order"))
    print("%s: RK4 %s, Euler %s" % (mode, rk4, euler))
    if not rk4 or rk4[0] != "FALSE CLAIM" or "order 2.0" not in rk4[1]:
        failures.append("%s: RK4's order is %s, expected FALSE CLAIM at order 2.00 (MuJoCo's own)" % (mode, rk4))
    if not euler or not euler[0].startswith("verified") or "order 1.0" not in euler[1]:
        failures.append("%s: Euler's order is %s, expected verified at order 1.00" % (mode, euler))
if len(found) == 2 and found["trusted"] != found["untrusted"]:
    for key in sorted(set(found["trusted"]) | set(found["untrusted"])):
        if found["trusted"].get(key) != found["untrusted"].get(key):
            failures.append("%s %s: trusted %s, untrusted %s" % (key[0], key[1], found["trusted"].get(key),
                                                                 found["untrusted"].get(key)))

# The control: a Node that cannot start (a stand-in) is the machine's, with its fix.
standin_dir = os.path.join(out, "standin")
os.makedirs(standin_dir)
standin = os.path.join(standin_dir, "node")
with open(standin, "w") as f:
    f.write("#!/bin/sh\necho 'stand-in Node: cannot reserve WebAssembly memory' >&2\nexit 1\n")
os.chmod(standin, 0o755)
os.chmod(out, 0o755)
os.chmod(standin_dir, 0o755)
for name, file in (("standin_javascript", os.path.join(engines, "mujoco_free_body.mjs")), ("standin_python", wrapper)):
    r, _ = check(name, file, "--untrusted", env={"GEOMECH_NODE": standin})
    print("%s: exit %d\n%s" % (name, r.returncode, r.stderr[-1500:]))
    if r.returncode != 3:
        failures.append("%s: exit %d, expected 3 (the grader's machine: Node does not start in the sandbox)"
                        % (name, r.returncode))
    for text in ("the grader's machine", "does not start in the sandbox", "cannot reserve WebAssembly memory",
                 "Fix: GEOMECH_NODE=/usr/bin/node"):
        if text not in r.stderr:
            failures.append("%s: the message does not say: %s" % (name, text))

for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
