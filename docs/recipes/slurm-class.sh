#!/bin/bash
# A class as a Slurm job array (issue 17): one task per shard, then a merge job that waits for
# the whole array. Submit with:
#   jobid=$(sbatch --parsable --array=1-16 docs/recipes/slurm-class.sh submissions reports)
#   sbatch --dependency=afterany:$jobid --wrap "geomech merge-class reports/class reports/shard-*"
#SBATCH --job-name=geomech-class
#SBATCH --cpus-per-task=2
#SBATCH --time=02:00:00
set -euo pipefail
folder=${1:?submissions folder}
out=${2:?reports folder}
n=${SLURM_ARRAY_TASK_COUNT:?run as a job array}
k=${SLURM_ARRAY_TASK_ID:?run as a job array}
geomech check-class "$folder" --shard "$k/$n" --parallel "${SLURM_CPUS_PER_TASK:-2}" --report "$out/shard-$k" || true
