#!/usr/bin/env bash
# Installs what is needed, builds LegoFeup Lab (release) and runs the standard experiment
# (step f of the guide: the tuned EKF, two laps of the arena) with the embedded simulator.
# Until the desktop application exists this is the main program; it prints where its
# results (trace.csv, summary.json, plots) went. Extra arguments go to `legofeup-cli run`.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install-deps.sh
cmake --preset release
cmake --build --preset release --target legofeup-cli

out="results/standard-experiment"
exec build/release/app/legofeup-cli run --experiment f --out "$out" "$@"
