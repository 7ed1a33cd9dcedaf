#!/usr/bin/env bash
# Builds the fuzz targets (clang, libFuzzer, ASan, UBSan) and runs each for N seconds (default 30)
# on its seed corpus in fuzz/corpus/<target>. New inputs go to a scratch directory, never into the
# repository; a crash leaves its input in the scratch directory and makes this script fail.
#   fuzz/run.sh [seconds] [target...]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
seconds=${1:-30}
shift || true
build=${GEOMECH_FUZZ_BUILD_DIR:-$root/build-fuzz}
if ! command -v clang++-14 >/dev/null 2>&1 || ! dpkg-query -W -f='${Status}' libclang-rt-14-dev 2>/dev/null | grep -q "install ok installed"; then
  if [ "$(id -u)" -eq 0 ]; then
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends clang-14 libclang-rt-14-dev >/dev/null
  else
    echo "fuzz/run.sh: needs clang-14 and libclang-rt-14-dev: sudo apt-get install -y clang-14 libclang-rt-14-dev" >&2
    exit 1
  fi
fi
[ -f "$build/CMakeCache.txt" ] || CXX=clang++-14 cmake -S "$root/fuzz" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" -j "${GEOMECH_JOBS:-2}" >/dev/null
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  for d in "$root"/fuzz/corpus/*/; do targets+=("$(basename "$d")"); done
fi
status=0
for t in "${targets[@]}"; do
  scratch=$(mktemp -d)
  echo "fuzz_$t: ${seconds}s on fuzz/corpus/$t (scratch $scratch)"
  if ! (cd "$scratch" && "$build/fuzz_$t" -max_total_time="$seconds" -max_len=16384 -print_final_stats=1 \
          "$scratch" "$root/fuzz/corpus/$t" > "$scratch/log" 2>&1); then
    echo "fuzz_$t FAILED; log and crashing input in $scratch" >&2
    tail -40 "$scratch/log" >&2
    status=1
  else
    grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$scratch/log" | sed "s/^/  /"
    rm -rf "$scratch"
  fi
done
exit $status
