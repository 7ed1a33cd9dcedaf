#!/usr/bin/env bash
# A complete C++ file with one mistake, checked from an empty cache, timed to its FIRST FIX line
# (the time a student waits for the first fix): examples/students/correct.hpp inlined into one file, with Euler's equations
# (3.8) written as (I^-1 Pi) x Pi instead of Pi x I^-1 Pi. Then the pieces of the double
# instantiation compiled one at a time, as `geomech check` compiles them (harness/program/build.cpp,
# kUnits): the precompiled header with an empty implementation, the slots other than Manakov's, the
# Manakov slots (the first look links these two, compiled at once), the integrators; and the first
# look's link with the default linker and with the fast one it uses.
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
piece() {  # piece LABEL FILE MACROS...
  local label=$1 file=$2; shift 2
  TIMEFORMAT="$label: $(printf '%s' "%R") s"
  { time "${flags[@]}" "$@" -c "$out/$file.cpp" -o "$out/$label.o" 2>/dev/null; } 2>&1
}
piece empty empty
piece other-slots one_mistake -DGEOMECH_SLOTS_PIECES=2 -DGEOMECH_SLOTS_PIECE=0 -DGEOMECH_SKIP_INTEGRATORS=1
piece manakov-slots one_mistake -DGEOMECH_SLOTS_PIECES=2 -DGEOMECH_SLOTS_PIECE=1 -DGEOMECH_SKIP_INTEGRATORS=1
piece integrators one_mistake -DGEOMECH_SLOTS_PIECES=0 -DGEOMECH_SLOTS_PIECE=0
piece whole-double one_mistake

# The first look's link, as `geomech check` ran it above, with the default linker and the fast one.
link=$(cat "$out"/cache/*/link-check-double.cmd)
fast=$(grep -o -- '-fuse-ld=[a-z]*' <<<"$link" || true)
for how in default "${fast:-}"; do
  [ -n "$how" ] || continue
  TIMEFORMAT="the first look's link ($how): $(printf '%s' "%R") s"
  { time bash -c "${link/ $fast/} ${how/default/}" >/dev/null 2>&1; } 2>&1
done
