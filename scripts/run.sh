#!/usr/bin/env bash
# Installs what is needed, builds LegoFeup Lab (release) and starts the desktop application
# with the embedded simulator (experiment f, the tuned filter; press Start). Extra arguments
# go to `legofeup` (see `legofeup --help`, e.g. --experiment a --large-text --start).
#
# On a machine without a display it says so and runs the same experiment headless with
# legofeup-cli instead, printing where the results (trace.csv, summary.json, plots) went.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install-deps.sh
cmake --preset release
if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
    echo "No display (DISPLAY and WAYLAND_DISPLAY are unset): running experiment f headless." >&2
    cmake --build --preset release --target legofeup-cli
    exec build/release/app/legofeup-cli run --experiment f --out results/standard-experiment
fi
cmake --build --preset release --target legofeup
exec build/release/app/legofeup "$@"
