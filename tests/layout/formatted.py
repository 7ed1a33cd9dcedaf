"""The project's own C++ is in its .clang-format style, includes sorted within each block
(docs/DEVELOPING.md, "Formatting"): clang-format --dry-run --Werror on every .cpp and .hpp of the
tree (the folders whose .clang-format disables formatting, examples/ and the tests' inputs, keep
their lines by that file). Prints "formatted: N files, 0 problems" or each file's first difference.

    python3 formatted.py PROJECT_DIR [CLANG_FORMAT]
"""
import os
import shutil
import subprocess
import sys

root = sys.argv[1]
tool = sys.argv[2] if len(sys.argv) > 2 else (shutil.which("clang-format") or "")
if not tool:
    print("formatted: clang-format is not installed (Debian's clang-format; the machine image has it)")
    sys.exit(77)
skip = {".git", "node_modules"}
files = []
for d, subdirs, names in os.walk(root):
    subdirs[:] = sorted(s for s in subdirs if s not in skip and not s.startswith("build"))
    files += [os.path.join(d, n) for n in sorted(names) if n.endswith((".cpp", ".hpp"))]
problems = []
for k in range(0, len(files), 64):
    r = subprocess.run([tool, "--dry-run", "--Werror", *files[k:k + 64]], capture_output=True, text=True)
    seen = set()
    for line in r.stderr.splitlines():
        if ": error: " in line:
            path = line.split(":", 1)[0]
            if path not in seen:
                seen.add(path)
                problems.append("%s: not in the .clang-format style (%s)" % (
                    os.path.relpath(path, root), line.split(": error: ", 1)[1]))
    if r.returncode != 0 and not seen:
        problems.append("clang-format failed (exit %d): %s" % (r.returncode, r.stderr[:300]))
for p in problems:
    print(p)
print("formatted: %d files, %d problems%s" % (len(files), len(problems),
      "" if not problems else "; fix: clang-format -i on each (docs/DEVELOPING.md, \"Formatting\")"))
sys.exit(1 if problems else 0)
