#!/bin/bash
# The Slurm recipe for a class (docs/recipes/slurm-class.sh) on a real one-node Slurm cluster:
# the class summary and gradebook that the job array and its merge job write are the same as those
# of one check-class run on one machine.
#
#   tests/scale/slurm_class.sh GEOMECH SOURCE OUT
#
# GEOMECH: the geomech program; SOURCE: the source tree (examples/class, docs/recipes); OUT: a
# folder for everything of the run (its earlier contents of the same names are removed first).
# Run as root, with Debian's slurmctld, slurmd and munge installed (tests/scale/slurm_one_node.sh
# starts the cluster in OUT/slurm, and this script always stops it again).
#
# The checks are narrowed to a few cheap ones (double only, six properties), the same for both
# runs. Both runs compile into the same cache folder, OUT/cache, and both start with it empty (the
# single run's is moved to OUT/cache-single before the jobs are submitted): neither profits from
# the other's builds, and the paths of the cache that reports name are the same in both. The wall
# time of each run is printed.
#
# Environment:
#   GEOMECH_PYTHON             default /usr/bin/python3 (the sandbox's user must be able to read the
#                              interpreter's folders, which a pyenv's under /root are not)
#   SLURM_CLASS_TIMEOUT        seconds to wait for the jobs (default 600)
#   SLURM_CLASS_CPUS_PER_TASK  default: the recipe's own --cpus-per-task (2: on a 2-core node the
#                              shards run one after the other; 1 lets them run at once)
#   SLURM_CLASS_TAMPER=1       a negative control: one grade of the merged gradebook is changed
#                              before the comparison, which must then say FAIL
# Exit status: 0 PASS, 1 FAIL (Slurm or munge not installed too: ./geomech test installs them), 77 skipped (not
# root, or no sandbox on this machine at all).
set -uo pipefail

[ $# -eq 3 ] || { echo "usage: $0 GEOMECH SOURCE OUT" >&2; exit 2; }
geomech=$(realpath "$1")
source_dir=$(realpath "$2")
mkdir -p "$3"
out=$(realpath "$3")
here=$(cd "$(dirname "$0")" && pwd)
timeout=${SLURM_CLASS_TIMEOUT:-600}
export GEOMECH_PYTHON=${GEOMECH_PYTHON:-/usr/bin/python3}

fail() {
  echo "FAIL: slurm_class: $*"
  exit 1
}
now() { date +%s.%N; }
seconds_since() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.1f", b - a }'; }

[ -x "$geomech" ] || fail "$geomech is not a program"
[ "$(id -u)" = 0 ] || { echo "SKIP: slurm_class: needs root (it starts slurmctld, slurmd and munged)"; exit 77; }
for p in slurmctld slurmd munged sbatch squeue sinfo scontrol scancel; do
  command -v $p >/dev/null || [ -x /usr/sbin/$p ] || {
    # ./geomech test installs them (test_packages): their absence is a broken set-up, not a skip.
    echo "FAIL: slurm_class: $p is not installed: apt-get install -y --no-install-recommends slurmctld slurmd munge (./geomech test installs them)"
    exit 1
  }
done
recipe=$source_dir/docs/recipes/slurm-class.sh
source "$(dirname "${BASH_SOURCE[0]}")/slurm_recipe.sh"
[ -f "$recipe" ] || fail "no recipe $recipe"
examples=$source_dir/examples/class
# Both runs must use the same program: a rebuild during the run (a developer's) is said, not compared.
program_print() { sha256sum "$geomech" | cut -d' ' -f1; }
program_at_start=$(program_print)

# What the run of a class is checked with, the same on one machine and in every shard.
checks=(--scalar double -p definition_hat -p definition_vee -p definition_casimir -p definition_manakov_Omega
        -p definition_manakov_2_34 -p integrator_order)
grading=(--rubric "$examples/rubric.json" --roster "$examples/roster.csv")

# A clean start: a cluster left running in OUT/slurm by an earlier run is stopped first.
[ -d "$out/slurm" ] && "$here/slurm_one_node.sh" "$out/slurm" stop
rm -rf "$out/slurm" "$out/class" "$out/single" "$out/single.csv" "$out/sharded" "$out/sharded.csv" \
  "$out/cache" "$out/cache-single" "$out/logs"
mkdir -p "$out/logs"

trap '"$here/slurm_one_node.sh" "$out/slurm" stop' EXIT
trap 'exit 130' INT
trap 'exit 143' TERM  # so that the EXIT trap stops the cluster on a signal too
"$here/slurm_one_node.sh" "$out/slurm" || fail "the one-node Slurm cluster did not start (logs: $out/slurm/log)"
export SLURM_CONF=$out/slurm/slurm.conf

cp -r "$examples/submissions" "$out/class"
cd "$out"

# --- one machine --------------------------------------------------------------------------------
t0=$(now)
"$geomech" check-class "$out/class" --report "$out/single" "${grading[@]}" --grades "$out/single.csv" \
  "${checks[@]}" --cache-dir "$out/cache" > "$out/logs/single.log" 2>&1
single_rc=$?
single_seconds=$(seconds_since "$t0")
echo "single machine: check-class exited $single_rc in $single_seconds s (log: $out/logs/single.log)"
if [ $single_rc = 3 ] && grep -q 'the sandbox (bubblewrap) does not work on this machine' "$out/logs/single.log"; then
  # As the other sandboxed tests: no sandbox on this machine at all is a skip. A sandbox that works
  # here but not in a Slurm job is a failure (the shards' check below).
  cat "$out/logs/single.log"
  echo "SKIP: slurm_class: the sandbox does not work on this machine"
  exit 77
fi
case $single_rc in 0|1) ;; *) cat "$out/logs/single.log"; fail "the single-machine run exited $single_rc" ;; esac
mv "$out/cache" "$out/cache-single"

# --- the recipe, as documented: a job array of 2 shards, then the merge job -------------------------
# The jobs find geomech on PATH (the recipe calls `geomech`): its folder goes first, and sbatch
# hands this environment (PATH, GEOMECH_PYTHON) to the jobs with --export=ALL.
export PATH="$(dirname "$geomech"):$PATH"
slurm_cpus=()
[ -n "${SLURM_CLASS_CPUS_PER_TASK:-}" ] && slurm_cpus=(--cpus-per-task="$SLURM_CLASS_CPUS_PER_TASK")
slurm_run_recipe "$recipe" "$out" "$out/class" "$out/sharded" "$out/cache" "$timeout" "$single_rc" "${checks[@]}" \
  -- "${grading[@]}" --grades "$out/sharded.csv"

echo "wall time: single machine $single_seconds s; Slurm, 2 shards and the merge $slurm_seconds s"
[ "$(program_print)" = "$program_at_start" ] || fail "$geomech changed (was rebuilt) during the run: the runs are not comparable; run again"

# --- the comparison --------------------------------------------------------------------------------
if [ "${SLURM_CLASS_TAMPER:-0}" = 1 ]; then  # the negative control: a grade that is not the single run's
  echo "negative control: alice's grade changed in the merged gradebook"
  cp "$out/sharded.csv" "$out/logs/sharded-untampered.csv"
  sed -i 's/^alice,\([^,]*,[^,]*,[^,]*\),[0-9.]*,/alice,\1,99.99,/' "$out/sharded.csv"
  cmp -s "$out/sharded.csv" "$out/logs/sharded-untampered.csv" && fail "negative control: no grade of alice's to change"
fi

# Byte for byte, nothing normalised. The runs differ in what the reports name in only one way
# that could show here: a compiled submission's cache entry is named for the hash of its source's
# absolute path inside the cache (harness/program/build.cpp, build_student), so two cache folders
# would give gina's "the compiler's full output: CACHE/gina-<hash>-sandboxed/double.log" two
# hashes; the one cache path above avoids that. Timings are in none of the files; the class folder
# and the rubric are named by the same absolute paths in both runs.
status=0
compare() {  # WHAT SINGLE MERGED
  [ -f "$2" ] || { echo "missing: $2"; status=1; return; }
  [ -f "$3" ] || { echo "missing: $3"; status=1; return; }
  if cmp -s "$2" "$3"; then
    echo "same: $1 ($(wc -l < "$2") lines, byte for byte)"
  else
    echo "DIFFERENT: $1"
    diff -u --label "single/$1" --label "merged/$1" "$2" "$3"
    status=1
  fi
}
compare summary.md "$out/single/summary.md" "$out/sharded/class/summary.md"
compare summary.html "$out/single/summary.html" "$out/sharded/class/summary.html"
compare gradebook.csv "$out/single.csv" "$out/sharded.csv"

if [ $status = 0 ]; then
  echo "PASS: slurm_class: the Slurm job array's merged summary (md, html) and gradebook equal the single-machine run's"
else
  echo "FAIL: slurm_class: the Slurm job array's merged outputs differ from the single-machine run's"
fi
exit $status
