"""ctest: what a submission sees of the machine in untrusted mode (docs/UNTRUSTED.md).

    python3 system_probe.py GEOMECH PEEK_SYSTEM_PY OUT_DIR [control]

examples/hostile/peek_system.py raises what it saw (accounts, host name, /usr/local, /etc). Checked
untrusted, it must see the sandbox's minimal system: the accounts root, nobody (and geomech when the
harness is not root), the name geomech-sandbox, an empty /usr/local, no /etc/shadow, /etc/hosts or
/etc/hostname, and of /etc only the entries docs/UNTRUSTED.md lists. With `control`, the same file
is checked in-process and must see the host's system (its accounts, /etc/shadow, a /usr/local with
something in it): proof that the test can fail.
"""
import json
import os
import re
import shutil
import socket
import subprocess
import sys

GEOMECH, FILE, OUT = sys.argv[1:4]
CONTROL = len(sys.argv) > 4 and sys.argv[4] == "control"
ALLOWED_ETC = re.compile(r"^(ld\.so\.cache|ld\.so\.conf|ld\.so\.conf\.d|alternatives|localtime|nsswitch\.conf|"
                         r"octaverc|python3.*|passwd|group)$")

shutil.rmtree(OUT, ignore_errors=True)
cmd = [GEOMECH, "check", FILE, "--scalar", "double", "-p", "definition_casimir", "--report", OUT]
if not CONTROL:
    cmd.append("--untrusted")
p = subprocess.run(cmd, capture_output=True, text=True, errors="replace", timeout=600)
report = open(os.path.join(OUT, "report.md"), encoding="utf-8", errors="replace").read()
m = re.search(r"system seen: (\{.*?\})\s*$", report, re.M)
if not m:
    sys.exit("the submission's message is not in the report (exit %d):\n%s%s" % (p.returncode, p.stdout, p.stderr))
seen = json.loads(m.group(1).replace("\\|", "|").replace("\\`", "`"))
print(("control, in-process" if CONTROL else "untrusted") + ": " + json.dumps(seen, sort_keys=True))

problems = []
if CONTROL:
    if not seen["shadow"]:
        problems.append("in-process the submission does not see /etc/shadow")
    if not seen["usr_local"]:
        problems.append("in-process the submission sees an empty /usr/local")
    if set(seen["users"]) <= {"root", "nobody", "geomech"}:
        problems.append("in-process the submission sees no account of the host beyond root and nobody")
    if problems:
        sys.exit("control: " + "; ".join(problems) + ": the untrusted test proves nothing")
    sys.exit(0)
if not set(seen["users"]) <= {"root", "nobody", "geomech"}:
    problems.append("accounts of the host are visible: %s" % seen["users"])
if seen["host"] != "geomech-sandbox":
    problems.append("the host's name is visible: %s" % seen["host"])
if seen["host"] == socket.gethostname():
    problems.append("the host's own name is visible")
if seen["usr_local"]:
    problems.append("/usr/local is visible: %s" % seen["usr_local"])
for key in ("shadow", "hosts", "hostname_file"):
    if seen[key]:
        problems.append("/etc/%s is visible" % key.replace("_file", ""))
extra = [e for e in seen["etc"] if not ALLOWED_ETC.match(e)]
if extra:
    problems.append("/etc holds more than the sandbox needs: %s" % extra)
if problems:
    sys.exit("; ".join(problems))
print("the submission saw the sandbox's minimal system")
