#!/bin/bash
# Runs scripts/slurm/sweep-array.sh as Slurm would, once per array task with
# SLURM_ARRAY_TASK_ID and SLURM_ARRAY_TASK_COUNT set (a small sweep), merges the shards and
# compares the result with the same sweep run unsharded: summary.json and cells.csv must be
# byte for byte the same.
# Usage: check_slurm_array.sh LEGOFEUP_CLI SCRIPT WORK_DIRECTORY
set -euo pipefail
cli="$1"
script="$2"
work="$3"
rm -rf "$work"
mkdir -p "$work"
export LEGOFEUP_CLI="$cli" LEGOFEUP_SHARDS="$work/shards" LEGOFEUP_Q="0.1,10" LEGOFEUP_R="0.1,10"
export LEGOFEUP_RUNS=1 LEGOFEUP_LAPS=1 SLURM_CPUS_PER_TASK=1 SLURM_ARRAY_TASK_COUNT=4
for task in 1 2 3 4; do
    SLURM_ARRAY_TASK_ID=$task bash "$script"
done
"$cli" merge --out "$work/merged" --no-plots --quiet "$work"/shards/sweep-shard-*-of-4.json
"$cli" sweep --experiment f --q "$LEGOFEUP_Q" --r "$LEGOFEUP_R" --runs 1 --laps 1 --jobs 2 \
    --out "$work/whole" --no-plots --quiet
cmp "$work/merged/summary.json" "$work/whole/summary.json"
cmp "$work/merged/cells.csv" "$work/whole/cells.csv"
echo "4 array tasks merged to the unsharded sweep"
