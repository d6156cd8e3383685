#!/bin/bash
# One shard of a Q × R sweep per task of a Slurm job array (docs/analysis.md). Submit it,
# then merge the shards once every task has finished:
#
#   job=$(sbatch --parsable scripts/slurm/sweep-array.sh)
#   sbatch --dependency=afterok:$job --wrap "legofeup-cli merge --out results shards/sweep-shard-*-of-4.json"
#
# Task i of n runs the cells i, i+n, i+2n, … of the grid and writes shards/sweep-shard-i-of-n.json.
# The settings below can be changed through the environment (sbatch --export=ALL,LEGOFEUP_RUNS=50 …).
#SBATCH --job-name=legofeup-sweep
#SBATCH --array=1-4
#SBATCH --cpus-per-task=2
#SBATCH --time=01:00:00
#SBATCH --output=sweep-%A_%a.log
set -euo pipefail

: "${SLURM_ARRAY_TASK_ID:?run this as a Slurm job array (sbatch), or set SLURM_ARRAY_TASK_ID}"
count="${SLURM_ARRAY_TASK_COUNT:-4}"
cli="${LEGOFEUP_CLI:-legofeup-cli}"

"$cli" sweep \
    --experiment "${LEGOFEUP_EXPERIMENT:-f}" \
    --q "${LEGOFEUP_Q:-1e-2:1e2:5}" \
    --r "${LEGOFEUP_R:-1e-2:1e2:5}" \
    --runs "${LEGOFEUP_RUNS:-20}" \
    --laps "${LEGOFEUP_LAPS:-2}" \
    --jobs "${SLURM_CPUS_PER_TASK:-0}" \
    --shard "${SLURM_ARRAY_TASK_ID}/${count}" \
    --out "${LEGOFEUP_SHARDS:-shards}" \
    --quiet
