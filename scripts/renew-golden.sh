#!/usr/bin/env bash
# Renews the golden trace, tests/golden/experiment_f_seed1.hash, when a change is meant to move
# the trajectories (docs/experiments.md, "Golden trace"): builds the golden test in the `dev`
# build (configuring it first if there is none), has it print the fingerprint of this build's
# run of experiment f, seed 1, writes it over the pinned file and prints the old and new
# hashes. Commit the file with the change that moved them.
#
# Usage: scripts/renew-golden.sh [BUILD_DIR]   (default build/dev)
set -euo pipefail
cd "$(dirname "$0")/.."

build=${1:-build/dev}
pinned=tests/golden/experiment_f_seed1.hash
if [[ ! -f $build/CMakeCache.txt ]]; then
    if [[ $build != build/dev ]]; then
        echo "error: $build is not a configured build directory" >&2
        exit 2
    fi
    cmake --preset dev
fi
cmake --build "$build" --target legofeup_golden_tests --parallel 2

fresh=$(mktemp)
trap 'rm -f "$fresh"' EXIT
"$build/tests/golden/legofeup_golden_tests" --print-pinned-text >"$fresh"

# `name value` of the trace, bits and rows lines of a pinned file ("none" when absent).
value_of() { awk -v name="$2" '$1 == name { print $2; found = 1 } END { if (!found) print "none" }' "$1"; }
for name in trace bits rows; do
    printf '%-6s old %-18s new %s\n' "$name" "$(value_of "$pinned" "$name")" \
        "$(value_of "$fresh" "$name")"
done
if cmp -s "$fresh" "$pinned"; then
    echo "Unchanged: $pinned already pins this build's trace."
    exit 0
fi
# The columns whose lines are new in the fresh file (diff exits 1 when the files differ).
changed=$({ diff <(grep '^column ' "$pinned" | sort) <(grep '^column ' "$fresh" | sort) || true; } |
    awk '$1 == ">" { printf " %s", $3 }')
echo "Columns changed or new:${changed:- none}"
cp "$fresh" "$pinned"
echo "Renewed $pinned: commit it with the change that moved the trace."
