#!/usr/bin/env bash
# Speed figures of the slot protocol: a full check of the correct Python and Octave implementations (every
# property, every scalar they provide), beside the same check of the C++ one in the same run, with
# the protocol's cost per call and the checks that took longest (where the time goes).
#   bench/remote_check.sh [build-dir]        (default: build; after ./geomech build)
#   THOROUGH=1 bench/remote_check.sh           also correct.py with --thorough: the costly 50-digit
#                                              runs a Python check leaves out, the ratio's other side
#   CLASS=1 bench/remote_check.sh              also a class of 20 (examples/students/*.cpp but bug_hang,
#                                              whose timeouts cost the same either way, and bug_nan)
#                                              untrusted against --trusted, empty caches, 2 at a time
#                                              (with THOROUGH=1 untrusted --thorough too); 10-20 min
# correct.m-script-server is correct.m through the script server in octave-cli.
# Prints one line per implementation: wall time, checks, TIMEOUTs, checks cut short by the case
# budget; then the 8 longest checks of each, then `geomech bench-protocol` for each language.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-$root/build}
geomech=$build/bin/geomech
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

# correct.m twice: with geomech-octave-server (Octave's interpreter linked in, where it is built) and
# with the script server in octave-cli, the alternative it is measured against.
runs=(examples/students/correct.cpp examples/students/correct.py examples/students/correct.m
      "examples/students/correct.m script")
[ "${THOROUGH:-0}" = 1 ] && runs+=("examples/students/correct.py --thorough")
for run in "${runs[@]}"; do
  read -r file extra <<<"$run"
  name=$(basename "$file")${extra:+$extra}
  start=$(date +%s.%N)
  status=0
  envs=()
  if [ "$extra" = script ]; then envs=(GEOMECH_OCTAVE_SERVER=script); extra=; name=$(basename "$file")-script-server; fi
  # shellcheck disable=SC2086
  (cd "$root" && env "${envs[@]}" "$geomech" check "$file" $extra --quiet --report "$out/$name" \
     >"$out/$name.log" 2>&1) || status=$?
  end=$(date +%s.%N)
  python3 - "$out/$name/verdicts.json" "$name" "$start" "$end" "$status" <<'EOF'
import json, sys
path, name, start, end, status = sys.argv[1:]
d = json.load(open(path))
vs = d["verdicts"] if isinstance(d, dict) else d
ran = [v for v in vs if v.get("outcome") != "NOT PROVIDED"]
timeouts = sum(1 for v in vs if v.get("outcome") == "TIMEOUT")
short = sum(1 for v in ran if v.get("cases_planned", 0) and v.get("cases", 0) < v.get("cases_planned", 0))
cpu = sum(v.get("seconds", 0) for v in ran)
print("%-12s wall %7.1f s  exit %s  %d checks (%.0f check-seconds)  %d TIMEOUT  %d ran fewer cases than planned  %d left to --thorough"
      % (name, float(end) - float(start), status, len(ran), cpu, timeouts, short, len(d.get("left_to_thorough", []))))
for v in sorted(ran, key=lambda v: -v.get("seconds", 0))[:8]:
    print("    %7.1f s  %-45s %-6s %s/%s cases" % (v.get("seconds", 0), v["property"], v["scalar"],
                                                  v.get("cases", "?"), v.get("cases_planned", "?")))
EOF
done
for file in examples/students/correct.py examples/students/correct.m; do
  echo "protocol cost, $file:"
  (cd "$root" && "$geomech" bench-protocol "$file") | sed 's/^/    /'
done
echo "protocol cost, examples/students/correct.m, the script server:"
(cd "$root" && GEOMECH_OCTAVE_SERVER=script "$geomech" bench-protocol examples/students/correct.m) | sed 's/^/    /'

if [ "${CLASS:-0}" = 1 ]; then
  mkdir -p "$out/class"
  for f in "$root"/examples/students/*.cpp "$root"/examples/students/correct.hpp; do
    case $(basename "$f") in bug_hang.cpp|bug_nan.cpp) ;; *) cp "$f" "$out/class/" ;; esac
  done
  modes=("untrusted:" "trusted:--trusted")
  [ "${THOROUGH:-0}" = 1 ] && modes+=("untrusted-thorough:--thorough")
  for m in "${modes[@]}"; do
    name=${m%%:*} flag=${m#*:}
    rm -rf "$out/cache-$name"
    start=$(date +%s.%N)
    status=0
    # shellcheck disable=SC2086
    "$geomech" check-class "$out/class" $flag --parallel 2 --cache-dir "$out/cache-$name" \
      --report "$out/class-$name" >"$out/class-$name.log" 2>&1 || status=$?
    end=$(date +%s.%N)
    wall=$(python3 -c "print('%.1f' % ($end - $start))")
    echo "class of 20, $name: wall $wall s, exit $status"
    eval "wall_${name//-/_}=$wall"
  done
  python3 -c "print('class of 20: untrusted / trusted = %.2fx' % ($wall_untrusted / $wall_trusted))"
fi
