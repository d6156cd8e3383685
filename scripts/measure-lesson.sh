#!/usr/bin/env bash
# Runs a lesson step on seeds 1..N and prints each summary metric's range over the seeds:
# how the thresholds next to the lessons' checks were measured.
#   scripts/measure-lesson.sh [--cli PATH] [--seeds N] <lesson>:<step> [metric ...]
# Example: scripts/measure-lesson.sh --seeds 20 beacons:b final_position_error_m
set -euo pipefail
cli=build/release/app/legofeup-cli
seeds=20
while [ $# -gt 0 ]; do
    case "$1" in
        --cli) cli=$2; shift 2 ;;
        --seeds) seeds=$2; shift 2 ;;
        *) break ;;
    esac
done
if [ $# -lt 1 ]; then
    echo "usage: $0 [--cli PATH] [--seeds N] <lesson>:<step> [metric ...]" >&2
    exit 2
fi
step=$1; shift
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for seed in $(seq 1 "$seeds"); do
    "$cli" run -e "$step" -s "$seed" -o "$out/$seed" --no-plots -q
done
python3 - "$out" "$seeds" "$@" <<'PY'
import json, sys
out, seeds, wanted = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
runs = []
for seed in range(1, seeds + 1):
    summary = json.load(open(f"{out}/{seed}/summary.json"))
    runs.append(summary.get("metrics", summary))
names = wanted or sorted(k for k, v in runs[0].items() if isinstance(v, (int, float)))
for name in names:
    values = [r[name] for r in runs if isinstance(r.get(name), (int, float))]
    if values:
        print(f"{name}: {min(values):.4g} – {max(values):.4g} (mean {sum(values)/len(values):.4g}, {len(values)} seeds)")
    else:
        print(f"{name}: not in the summaries")
PY
