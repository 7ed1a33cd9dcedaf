"""The control of ctest docs.engine_ledger_current: a copy of docs/ENGINES.md whose ledger has one
verdict changed is refused, naming the line and the command that regenerates it; the copy written
back by --write is current again.

    python3 engine_ledger_control.py PROJECT_DIR BUILD_DIR OUT_DIR
"""
import os
import shutil
import subprocess
import sys

project, build, out = sys.argv[1:4]
ledger = os.path.join(project, "tools", "engine_ledger.py")
shutil.rmtree(out, ignore_errors=True)
os.makedirs(out)
copy = os.path.join(out, "ENGINES.md")
shutil.copy(os.path.join(project, "docs", "ENGINES.md"), copy)
with open(copy) as f:
    text = f.read()
if "| **FALSE CLAIM** |" not in text:
    sys.exit("FAIL: docs/ENGINES.md's ledger holds no FALSE CLAIM row to change")
with open(copy, "w") as f:
    f.write(text.replace("| **FALSE CLAIM** |", "| verified |", 1))
failures = []
r = subprocess.run([sys.executable, ledger, project, build, "--check", copy], capture_output=True, text=True)
print(r.stdout + r.stderr)
if r.returncode != 1 or "regenerate it with ./geomech ledger" not in r.stdout or "first difference" not in r.stdout:
    failures.append("a ledger one verdict off was not refused with its line and fix (exit %d)" % r.returncode)
r = subprocess.run([sys.executable, ledger, project, build, "--write", copy], capture_output=True, text=True)
r2 = subprocess.run([sys.executable, ledger, project, build, "--check", copy], capture_output=True, text=True)
print(r.stdout + r2.stdout)
if r.returncode != 0 or r2.returncode != 0:
    failures.append("the ledger written back by --write is not current (exit %d, then %d)" % (r.returncode, r2.returncode))
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
