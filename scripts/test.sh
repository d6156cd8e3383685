#!/usr/bin/env bash
# Installs what is needed, builds, and runs every test: the warnings-as-errors `dev` build,
# the AddressSanitizer + UndefinedBehaviorSanitizer `asan` build, and a bounded run of every
# fuzzer (the protocol decoders and the readers of the files users hand in). Each phase
# prints how long it took, so a slow step shows where it is.
set -euo pipefail
cd "$(dirname "$0")/.."

phase_start=$SECONDS
phase() {
    echo "== $1 ($((SECONDS - phase_start)) s so far)"
}

phase "install the Debian packages"
scripts/install-deps.sh

for preset in dev asan; do
    phase "$preset: configure, build, test"
    cmake --preset "$preset"
    cmake --build --preset "$preset"
    ctest --preset "$preset"
done
phase "fuzz: every fuzzer, 10 s each"
scripts/fuzz.sh 10
phase "done"
echo "All tests passed (dev, asan and fuzz) in $((SECONDS - phase_start)) s."
