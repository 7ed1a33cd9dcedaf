#!/usr/bin/env bash
# Builds the fuzz targets (clang, libFuzzer, ASan, UBSan) and runs each for N seconds (default 30),
# as many at once as there are cores,
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
# The targets run side by side, as many at a time as there are jobs (each fuzzer is one process):
# on 2 cores, three targets of N seconds take 2N instead of 3N, each still fuzzed for its N seconds.
jobs=${GEOMECH_JOBS:-$(nproc 2>/dev/null || echo 2)}
results=$(mktemp -d)
fuzz_one() {
  local t=$1 scratch
  scratch=$(mktemp -d)
  if ! (cd "$scratch" && "$build/fuzz_$t" -max_total_time="$seconds" -max_len=16384 -print_final_stats=1 \
          "$scratch" "$root/fuzz/corpus/$t" > "$scratch/log" 2>&1); then
    { echo "fuzz_$t FAILED; log and crashing input in $scratch"; tail -40 "$scratch/log"; } > "$results/$t.out"
    touch "$results/$t.failed"
    return
  fi
  { echo "fuzz_$t: ${seconds}s on fuzz/corpus/$t"
    grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$scratch/log" | sed "s/^/  /" || true; } > "$results/$t.out"
  rm -rf "$scratch"
}
running=0
for t in "${targets[@]}"; do
  fuzz_one "$t" &
  running=$((running + 1))
  if [ "$running" -ge "$jobs" ]; then
    wait -n || true
    running=$((running - 1))
  fi
done
wait
status=0
for t in "${targets[@]}"; do
  if [ -f "$results/$t.failed" ]; then
    cat "$results/$t.out" >&2
    status=1
  else
    cat "$results/$t.out"
  fi
done
rm -rf "$results"
exit $status
