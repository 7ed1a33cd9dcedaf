#!/bin/bash
# A class as a Slurm job array: one task per shard, then a merge job that waits for
# the whole array and writes the class's summary and gradebook. Submit with:
#   jobid=$(sbatch --parsable --array=1-16 docs/recipes/slurm-class.sh submissions reports [OPTIONS...])
#   sbatch --dependency=afterany:$jobid --wrap "geomech merge-class reports/class reports/shard-* \
#       --rubric rubric.json --roster roster.csv --grades grades.csv"
# OPTIONS after the two folders go to every shard's check-class as they are (the checks: -p,
# --scalar, --timeout, --cache-dir, ...); give every shard the same. The gradebook's options
# (--grades, --rubric, --roster, --feedback-dir) belong to the merge job, which sees the whole class.
# tests/scale/slurm_class.sh runs this recipe on a one-node Slurm cluster.
#SBATCH --job-name=geomech-class
#SBATCH --cpus-per-task=2
#SBATCH --time=02:00:00
set -euo pipefail
folder=${1:?submissions folder}
out=${2:?reports folder}
shift 2
n=${SLURM_ARRAY_TASK_COUNT:?run as a job array}
k=${SLURM_ARRAY_TASK_ID:?run as a job array}
# Exit status 1: a student did not pass, and the shard's results are written; any other (bad
# options, the grader's machine) fails the task.
geomech check-class "$folder" --shard "$k/$n" --parallel "${SLURM_CPUS_PER_TASK:-2}" --report "$out/shard-$k" "$@" ||
  [ $? -eq 1 ]
