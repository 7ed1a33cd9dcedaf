#!/bin/bash
# Class mode on a generated class of N: how many submissions a minute `geomech check-class` grades
# on this machine and, with --slurm, as the Slurm recipe's 2-shard job array plus its merge job.
#
#   bench/class_of_n.sh GEOMECH SOURCE OUT [N] [--slurm]
#
# GEOMECH: the geomech program (build/bin/geomech); SOURCE: the source tree (examples/class,
# docs/recipes, tests/scale); OUT: a folder for everything of the run (what this script writes
# there is removed first); N: the class size (default 200).
#
# 1. OUT/class: N submissions made from the ready class examples/class/submissions (README.md
#    there), taken in turn in name order (alice.py, bob.py, carol.m, dave/, erin.cpp, frank.py,
#    gina.cpp, alice.py, ...), each under a new student name that keeps the file's extension or
#    the folder form: student001_alice.py, student002_bob.py, student003_carol.m, student004_dave/,
#    ... So the class mixes Python, Octave and C++, right, wrong, incomplete and not compiling.
#    Deterministic: the same N gives the same class.
# 2. One check-class run on this machine, with the checks narrowed (double only, seven properties)
#    so that a class of 200 takes minutes, into OUT/single, OUT/single.csv and the empty cache
#    OUT/cache-single. Its wall time and submissions per minute are printed, with the class by
#    language and by result (from the gradebook's feedback and summary.md's table).
# 3. With --slurm (root; Debian's slurmctld, slurmd and munge): a one-node Slurm cluster in
#    OUT/slurm (tests/scale/slurm_one_node.sh, stopped again on any exit), the same class as the
#    recipe docs/recipes/slurm-class.sh's job array of 2 shards plus the merge job, as
#    tests/scale/slurm_class.sh submits them; timed from the first sbatch to the merge job's end.
#    Its figure is printed the same way, and whether its merged gradebook (and summary) equals the
#    single run's byte for byte.
#
# The C++ build cache is keyed by PATH, not by content: harness/program/build.cpp, build_student,
# compiles into CACHE/<name>-<fnv1a of the source's canonical path>[-sandboxed], and in a class the
# source is the student's own snapshot, CACHE/class-<hash of the class folder>/submissions/<name>/
# (harness/class/class_mode.cpp). So the N/7 copies of erin.cpp are each compiled (and each copy of
# gina.cpp fails to compile on its own): the figure includes one build per C++ submission, as a
# real class of different files would. The script counts the build folders in the cache to show it.
# For the same reason the Slurm run is given the same cache path as the single run, emptied: the
# single run's cache is set aside meanwhile (kept as OUT/cache-single afterwards, the Slurm run's as
# OUT/cache-slurm), so that neither profits from the other's builds and the compiler-output paths
# that the reports name (gina's CACHE/...-sandboxed/double.log) are the same in both.
#
# Environment:
#   GEOMECH_PYTHON            default /usr/bin/python3 (the sandbox must be able to read it; a pyenv
#                             under /root is not readable there)
#   CLASS_OF_N_TIMEOUT        seconds to wait for the Slurm jobs (default 600 + 60 per submission)
#   CLASS_OF_N_CPUS_PER_TASK  the shards' --cpus-per-task (default: the recipe's own, 2: on a 2-core
#                             node the two shards then run one after the other, each 2 at a time)
# Exit status: 0 when every step worked (whatever the students' results), 1 on any failure, with a
# message starting "class_of_n: FAIL:"; 2 for bad usage.
set -uo pipefail

usage() { echo "usage: $0 GEOMECH SOURCE OUT [N] [--slurm]" >&2; exit 2; }
say() { echo "class_of_n: $*"; }
fail() {
  echo "class_of_n: FAIL: $*" >&2
  exit 1
}
now() { date +%s.%N; }
seconds_since() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.1f", b - a }'; }
per_minute() { awk -v n="$1" -v s="$2" 'BEGIN { if (s > 0) printf "%.1f", 60 * n / s; else print "inf" }'; }

# --- arguments ------------------------------------------------------------------------------------
slurm=no
args=()
for a in "$@"; do
  case $a in
    --slurm) slurm=yes ;;
    -h|--help) usage ;;
    -*) echo "class_of_n: unknown option $a" >&2; usage ;;
    *) args+=("$a") ;;
  esac
done
[ ${#args[@]} -ge 3 ] && [ ${#args[@]} -le 4 ] || usage
n=${args[3]:-200}
[[ $n =~ ^[0-9]+$ ]] && [ "$n" -ge 1 ] || fail "N must be a whole number of at least 1, not '$n'"
n=$((10#$n))
[ -x "${args[0]}" ] && [ -f "${args[0]}" ] || fail "${args[0]} is not a program (GEOMECH; is the build being replaced? try again)"
geomech=$(realpath "${args[0]}")
[ -d "${args[1]}" ] || fail "${args[1]} is not a folder (SOURCE)"
source_dir=$(realpath "${args[1]}")
mkdir -p "${args[2]}" || fail "cannot create ${args[2]}"
out=$(realpath "${args[2]}")
examples=$source_dir/examples/class
templates_dir=$examples/submissions
rubric=$examples/rubric.json
one_node=$source_dir/tests/scale/slurm_one_node.sh
recipe=$source_dir/docs/recipes/slurm-class.sh
source "$source_dir/tests/scale/slurm_recipe.sh"
[ -d "$templates_dir" ] || fail "no ready class $templates_dir"
[ -f "$rubric" ] || fail "no rubric $rubric"
export GEOMECH_PYTHON=${GEOMECH_PYTHON:-/usr/bin/python3}
[ -x "$GEOMECH_PYTHON" ] || fail "GEOMECH_PYTHON=$GEOMECH_PYTHON is not a program"
timeout=${CLASS_OF_N_TIMEOUT:-$((600 + 60 * n))}

if [ $slurm = yes ]; then
  [ "$(id -u)" = 0 ] || fail "--slurm needs root (tests/scale/slurm_one_node.sh starts slurmctld, slurmd and munged)"
  [ -x "$one_node" ] || [ -f "$one_node" ] || fail "no $one_node"
  [ -f "$recipe" ] || fail "no recipe $recipe"
  for p in slurmctld slurmd munged sbatch squeue scontrol scancel; do
    command -v $p >/dev/null || [ -x /usr/sbin/$p ] ||
      fail "$p is not installed: apt-get install -y --no-install-recommends slurmctld slurmd munge"
  done
fi

# The checks, the same on one machine and in every shard (the brief's narrowed set: a class of 200
# in minutes).
checks=(--scalar double -p definition_hat -p definition_vee -p definition_casimir -p definition_euler_3_8
        -p definition_manakov_Omega -p definition_manakov_2_34 -p integrator_order)
program_print() { sha256sum "$geomech" 2>/dev/null | cut -d' ' -f1; }
program_at_start=$(program_print)

# A clean start: a cluster left running in OUT/slurm by an earlier run is stopped first.
if [ -d "$out/slurm" ]; then
  bash "$one_node" "$out/slurm" stop || fail "could not stop the cluster left in $out/slurm"
fi
rm -rf "$out/class" "$out/single" "$out/single.csv" "$out/cache-single" "$out/cache-single.kept" \
  "$out/cache-slurm" "$out/sharded" "$out/sharded.csv" "$out/slurm" "$out/logs" ||
  fail "cannot clear the earlier run's files in $out"
mkdir -p "$out/logs" || fail "cannot create $out/logs"

# --- 1. the class -----------------------------------------------------------------------------------
templates=()
while IFS= read -r t; do templates+=("$t"); done < <(cd "$templates_dir" && LC_ALL=C ls -1 | LC_ALL=C sort)
[ ${#templates[@]} -gt 0 ] || fail "the ready class $templates_dir is empty"
mkdir -p "$out/class" || fail "cannot create $out/class"
declare -A by_language=()
language_of() {  # a submission's name: its language
  case $1 in
    *.py) echo Python ;;
    *.m) echo Octave ;;
    *.cpp|*.cc) echo C++ ;;
    *) [ -d "$templates_dir/$1" ] && echo Octave || echo other ;;  # dave/: Octave function files
  esac
}
declare -A student_template=()
for ((i = 1; i <= n; i++)); do
  t=${templates[$(((i - 1) % ${#templates[@]}))]}
  name=$(printf 'student%03d_%s' "$i" "$t")
  cp -r "$templates_dir/$t" "$out/class/$name" || fail "cannot copy $t to $out/class/$name"
  lang=$(language_of "$t")
  by_language[$lang]=$((${by_language[$lang]:-0} + 1))
  student_template[${name%.*}]=$t
done
cpp_count=${by_language[C++]:-0}
language_line=$(for l in "${!by_language[@]}"; do echo "$l ${by_language[$l]}"; done | LC_ALL=C sort | paste -sd, - | sed 's/,/, /g')
say "class of $n in $out/class, from ${templates[*]} in turn: $language_line"

# --- counting the results ---------------------------------------------------------------------------
# The verdict of each student, as the ready class's README names them: from the gradebook (every
# student a row: name, grade, feedback) and, for the status, summary.md's table.
python_count() {  # GRADEBOOK SUMMARY.MD: prints "DOES NOT COMPILE a, FAIL b, ..."; "NAME VERDICT" lines on stderr
  "$GEOMECH_PYTHON" - "$@" <<'EOF'
import csv, re, sys, collections
book, summary = sys.argv[1], sys.argv[2]
with open(book, newline='') as f:
    rows = list(csv.DictReader(f))
names = [r.get('name') or next(iter(r.values())) for r in rows]
# summary.md: the table's rows name each student in their first cell; the verdict is the cell in
# capitals (PASS, FAIL, INCOMPLETE, DOES NOT COMPILE, NOT CHECKED, ...).
verdict = {}
for line in open(summary, encoding='utf-8'):
    if not line.startswith('|'):
        continue
    cells = [c.strip() for c in line.strip().strip('|').split('|')]
    if not cells:
        continue
    first = re.sub(r'[`*\[\]]|\(.*?\)', '', cells[0]).strip()
    if first in names and first not in verdict:
        for c in cells[1:]:
            m = re.match(r'\**(PASS|FAIL|INCOMPLETE|DOES NOT COMPILE|NOT CHECKED|GRADER ERROR|NO SUBMISSION|NOT READ)\b', c)
            if m:
                verdict[first] = m.group(1)
                break
counts = collections.Counter(verdict.get(n, 'unknown') for n in names)
print(', '.join(f'{k} {v}' for k, v in sorted(counts.items())))
for n in names:
    print(f'{n} {verdict.get(n, "unknown")}', file=sys.stderr)
EOF
}

# --- 2. one machine -----------------------------------------------------------------------------------
say "single machine: $(basename "$geomech") check-class ... (log: $out/logs/single.log)"
t0=$(now)
(cd "$out" && "$geomech" check-class "$out/class" --report "$out/single" --rubric "$rubric" \
  --grades "$out/single.csv" --cache-dir "$out/cache-single" "${checks[@]}") > "$out/logs/single.log" 2>&1
single_rc=$?
single_seconds=$(seconds_since "$t0")
case $single_rc in
  0|1) ;;  # 1: a student did not pass, which this class always has
  *) tail -n 30 "$out/logs/single.log" >&2
     fail "the single-machine check-class exited $single_rc after $single_seconds s (log: $out/logs/single.log)" ;;
esac
[ -s "$out/single.csv" ] || fail "the single-machine run wrote no gradebook $out/single.csv"
[ -s "$out/single/summary.md" ] || fail "the single-machine run wrote no $out/single/summary.md"
single_results=$(python_count "$out/single.csv" "$out/single/summary.md" 2> "$out/logs/single-verdicts.txt") ||
  fail "cannot read the results of $out/single.csv and $out/single/summary.md"
rows=$(($(wc -l < "$out/single.csv") - 1))
[ "$rows" = "$n" ] || fail "the gradebook $out/single.csv has $rows rows for a class of $n"
grep -q ' unknown$' "$out/logs/single-verdicts.txt" &&
  fail "summary.md gives no verdict for some students (see $out/logs/single-verdicts.txt)"
# Each template's copies must all get the same verdict (they are the same file).
while read -r who verdict; do
  echo "${student_template[$who]:-?} $verdict"
done < "$out/logs/single-verdicts.txt" | sort -u > "$out/logs/single-verdict-by-template.txt"
uneven=$(cut -d' ' -f1 "$out/logs/single-verdict-by-template.txt" | uniq -d)
[ -z "$uneven" ] && same_verdicts="every copy of a template got the same verdict" ||
  same_verdicts="copies of $(echo $uneven) got DIFFERENT verdicts (see $out/logs/single-verdict-by-template.txt)"
build_dirs=$(find "$out/cache-single" -mindepth 1 -maxdepth 1 -type d -name 'student*' 2>/dev/null | wc -l)
single_rate=$(per_minute "$n" "$single_seconds")

echo
echo "== single machine: class of $n ($(nproc) cores) =="
echo "by language: $language_line"
echo "by result:   $single_results ($same_verdicts; $(paste -sd';' "$out/logs/single-verdict-by-template.txt" | sed 's/;/; /g'))"
echo "check-class exit status $single_rc; wall $single_seconds s; $single_rate submissions/min"
echo "C++ build cache: keyed by PATH, not content (harness/program/build.cpp, build_student:" \
  "CACHE/<name>-<fnv1a(canonical source path)>; the source is the student's snapshot under" \
  "CACHE/class-<hash>/submissions/<name>/). $build_dirs build folders for $cpp_count C++ submissions:" \
  "every copy is compiled, none reuses another's build"
echo

summary_line="class of $n: single machine $single_seconds s, $single_rate submissions/min"

# --- 3. Slurm -----------------------------------------------------------------------------------------
if [ $slurm = yes ]; then
  cluster_started=no
  stop_cluster() {
    [ $cluster_started = yes ] || return 0
    cluster_started=no
    bash "$one_node" "$out/slurm" stop >> "$out/logs/slurm-stop.log" 2>&1 ||
      echo "class_of_n: WARNING: stopping the cluster in $out/slurm failed (log: $out/logs/slurm-stop.log)" >&2
  }
  restore_cache() {  # the single run's cache back under its name
    if [ -d "$out/cache-single.kept" ]; then
      [ -e "$out/cache-single" ] && mv "$out/cache-single" "$out/cache-slurm"
      mv "$out/cache-single.kept" "$out/cache-single"
    fi
  }
  trap 'stop_cluster; restore_cache' EXIT
  trap 'exit 130' INT
  trap 'exit 143' TERM  # so that the EXIT trap stops the cluster on a signal too
  cluster_started=yes  # from here the EXIT trap stops whatever part of it came up
  bash "$one_node" "$out/slurm" > "$out/logs/slurm-start.log" 2>&1 || {
    cat "$out/logs/slurm-start.log" >&2
    fail "the one-node Slurm cluster did not start (logs: $out/slurm/log, $out/logs/slurm-start.log)"
  }
  export SLURM_CONF=$out/slurm/slurm.conf
  PATH="$(dirname "$geomech"):$PATH:/usr/sbin"; export PATH  # the recipe and the merge job call `geomech`

  # The same cache path as the single run's, emptied (see the top of this file).
  mv "$out/cache-single" "$out/cache-single.kept" || fail "cannot set the single run's cache aside"
  slurm_cpus=()
  [ -n "${CLASS_OF_N_CPUS_PER_TASK:-}" ] && slurm_cpus=(--cpus-per-task="$CLASS_OF_N_CPUS_PER_TASK")
  recipe_cpus=$(sed -n "s/^#SBATCH --cpus-per-task=\([0-9]*\).*/\1/p" "$recipe" | head -n1)
  cpus_said="${recipe_cpus:-?} (the recipe's)"
  [ -n "${CLASS_OF_N_CPUS_PER_TASK:-}" ] && cpus_said=$CLASS_OF_N_CPUS_PER_TASK
  say "slurm: --cpus-per-task $cpus_said; waiting up to $timeout s"
  slurm_run_recipe "$recipe" "$out" "$out/class" "$out/sharded" "$out/cache-single" "$timeout" "$single_rc" "${checks[@]}" \
    -- --rubric "$rubric" --grades "$out/sharded.csv"
  echo "  (the merge job exits 1, FAILED 1:0 to Slurm, when a student did not pass, as check-class does; the single run exited $single_rc)"
  [ -s "$out/sharded.csv" ] || fail "the merge job wrote no gradebook $out/sharded.csv"
  slurm_results=$(python_count "$out/sharded.csv" "$out/sharded/class/summary.md" 2>/dev/null) ||
    fail "cannot read the results of $out/sharded.csv and $out/sharded/class/summary.md"
  stop_cluster
  restore_cache

  if cmp -s "$out/single.csv" "$out/sharded.csv"; then
    gradebook_same="EQUALS the single run's, byte for byte ($rows rows)"
    gradebook_ok=yes
  else
    diff -u --label single.csv --label sharded.csv "$out/single.csv" "$out/sharded.csv" > "$out/logs/gradebook.diff"
    gradebook_same="DIFFERS from the single run's (diff: $out/logs/gradebook.diff)"
    gradebook_ok=no
  fi
  cmp -s "$out/single/summary.md" "$out/sharded/class/summary.md" && summary_same="equals" || summary_same="DIFFERS from"
  slurm_rate=$(per_minute "$n" "$slurm_seconds")

  echo
  echo "== Slurm, one node: job array of 2 shards + merge, class of $n =="
  echo "by result:   $slurm_results"
  echo "merged gradebook $out/sharded.csv $gradebook_same; merged summary.md $summary_same the single run's"
  echo "submission to the merge job's end: wall $slurm_seconds s; $slurm_rate submissions/min"
  echo
  summary_line+="; Slurm 2 shards $slurm_seconds s, $slurm_rate submissions/min"
fi

if [ "$(program_print)" != "$program_at_start" ]; then
  echo "class_of_n: WARNING: $geomech changed (was rebuilt) during the run: the figures may mix two builds" >&2
fi
echo "$summary_line"
if [ $slurm = yes ] && [ $gradebook_ok != yes ]; then
  fail "the merged gradebook differs from the single-machine run's ($out/logs/gradebook.diff)"
fi
exit 0
