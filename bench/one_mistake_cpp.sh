#!/usr/bin/env bash
# A complete C++ file with one mistake, checked from an empty cache, timed to its FIRST FIX line
# (issue 56, item 3): examples/students/correct.hpp inlined into one file, with Euler's equations
# (3.8) written as (I^-1 Pi) x Pi instead of Pi x I^-1 Pi. Then the double instantiation's compile
# alone, split into what it costs: the precompiled header and an empty implementation, the
# implementation's slots, and its integrators.
#   bench/one_mistake_cpp.sh [build-dir]        (default: build; after ./geomech build)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-$root/build}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
impl='course::RigidBody, course::Midpoint, course::Splitting, course::ClebschMidpoint'
make_file() {  # make_file FILE "GEOMECH_STUDENT arguments"
  sed -e 's/return P.cross(P.cwiseQuotient(I));/return (P.cwiseQuotient(I)).cross(P);/' \
      -e '/^#pragma once$/d' "$root/examples/students/correct.hpp" > "$1"
  grep -q 'cwiseQuotient(I)).cross(P)' "$1" || { echo "bench: the mistake was not made (correct.hpp changed?)" >&2; exit 2; }
  echo "GEOMECH_STUDENT($2);" >> "$1"
}
make_file "$out/one_mistake.cpp" "$impl"
python3 "$root/bench/first_failure.py" "$build/bin/geomech" check "$out/one_mistake.cpp" --cache-dir "$out/cache"

# The compile of the double instantiation, as `geomech check` runs it (flags from the toolchain).
read -r -a flags < <(python3 - "$build/student/toolchain.json" <<'PY'
import json, sys
t = json.load(open(sys.argv[1]))
out = [t["cxx"]] + t["flags"] + [t["opt"]["double"], "-DGEOMECH_STUDENT_ONLY=0", "-DGEOMECH_STUDENT_CHECK=1"]
if t.get("precompiled_header"):
    out += ["-include", t["precompiled_header"]]
out += ["-include", [i for i in t["includes"] if i.endswith("student")][0] + "/geomech/detail/scalar_selection.hpp"]
out += ["-I" + i for i in t["includes"]]
print(" ".join(out))
PY
)
printf '#include <geomech/student.hpp>\nstruct Nothing {};\nGEOMECH_STUDENT(Nothing);\n' > "$out/empty.cpp"
make_file "$out/slots_only.cpp" "course::RigidBody"
for f in empty slots_only one_mistake; do
  TIMEFORMAT="$f: the compile in double, $(printf '%s' "%R") s"
  { time "${flags[@]}" -c "$out/$f.cpp" -o "$out/$f.o" 2>/dev/null; } 2>&1
done
