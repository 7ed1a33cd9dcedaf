# The class recipe (docs/recipes/slurm-class.sh) submitted as documented to a running cluster, and
# waited for: sourced by tests/scale/slurm_class.sh and bench/class_of_n.sh. The caller defines
# `fail MESSAGE` and `now`/`seconds_since T0`, exports SLURM_CONF and puts geomech first on PATH.
#
#   slurm_run_recipe RECIPE OUT CLASS SHARDED CACHE TIMEOUT SINGLE_RC [CHECK OPTIONS...] -- [MERGE OPTIONS...]
#
# Submits a job array of 2 shards (RECIPE CLASS SHARDED CHECK OPTIONS --cache-dir CACHE; logs in
# OUT/logs; $slurm_cpus, an array, may hold --cpus-per-task=N), then the merge job
# (`geomech merge-class SHARDED/class SHARDED/shard-* MERGE OPTIONS`), waits up to TIMEOUT s until
# neither is pending, running or completing, prints how each job ended, and fails unless every shard
# COMPLETED 0:0 and the merge job exited as the single-machine run did (SINGLE_RC: 1 when a student
# did not pass, which Slurm shows as FAILED 1:0). Sets slurm_seconds: submission to the last end.
slurm_run_recipe() {
  local recipe=$1 out=$2 class=$3 sharded=$4 cache=$5 timeout=$6 single_rc=$7
  shift 7
  local checks=() merge_options=()
  while [ $# -gt 0 ] && [ "$1" != -- ]; do checks+=("$1"); shift; done
  [ $# -gt 0 ] && shift
  merge_options=("$@")
  local t0 array merge merge_cmd left deadline
  t0=$(now)
  array=$(sbatch --parsable --export=ALL --array=1-2 "${slurm_cpus[@]}" --chdir="$out" --output="$out/logs/shard-%a.out" \
    "$recipe" "$class" "$sharded" "${checks[@]}" --cache-dir "$cache" 2> "$out/logs/sbatch.err") ||
    { cat "$out/logs/sbatch.err" >&2; fail "sbatch of the job array failed"; }
  merge_cmd="$(printf '%q ' geomech merge-class "$sharded/class")$(printf '%q' "$sharded")/shard-* $(printf '%q ' "${merge_options[@]}")"
  merge=$(sbatch --parsable --export=ALL --dependency=afterany:"$array" --chdir="$out" --output="$out/logs/merge.out" \
    --job-name=geomech-merge --wrap "$merge_cmd" 2> "$out/logs/sbatch.err") ||
    { cat "$out/logs/sbatch.err" >&2; fail "sbatch of the merge job failed"; }
  echo "slurm: job array $array (2 shards), merge job $merge: $merge_cmd"

  deadline=$((SECONDS + timeout))
  while :; do
    left=$(squeue -h --jobs="$array,$merge" -o %i 2>&1) || fail "squeue failed: $left"
    [ -z "$left" ] && break
    [ $SECONDS -lt $deadline ] || { squeue --jobs="$array,$merge" >&2; fail "the Slurm jobs did not finish in $timeout s"; }
    sleep 0.5
  done
  slurm_seconds=$(seconds_since "$t0")

  echo "slurm: the jobs ended in $slurm_seconds s (submission to the last job's end):"
  slurm_job_states "$array" | sed 's/^/  /'
  slurm_job_states "$merge" | sed 's/^/  /'
  local bad_shards merge_exit
  bad_shards=$(slurm_job_states "$array" | awk '$2 != "COMPLETED" || $3 != "0:0"')
  [ -z "$bad_shards" ] || { tail -n 30 "$out"/logs/shard-*.out >&2; fail "a shard did not complete: $bad_shards"; }
  merge_exit=$(slurm_job_states "$merge" | awk '{ split($3, e, ":"); print e[1] }')
  [ "$merge_exit" = "$single_rc" ] ||
    { cat "$out/logs/merge.out" >&2; fail "the merge job exited ${merge_exit:-?}, the single-machine run $single_rc"; }
}

# How each job ended (kept by slurmctld for MinJobAge, 5 min: no accounting database here).
slurm_job_states() {  # JOBID: one line per job (array task): id, state, exit code, start and end
  scontrol show job -o "$1" | while read -r line; do
    tr ' ' '\n' <<< "$line" | awk -F= '
      $1 == "JobId" { id = $2 } $1 == "ArrayJobId" { id = $2 } $1 == "ArrayTaskId" { id = id "_" $2 }
      { v[$1] = $2 } END { print id, v["JobState"], v["ExitCode"], v["StartTime"], v["EndTime"] }'
  done | sort
}
