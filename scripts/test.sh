#!/usr/bin/env bash
# Installs what is needed, builds, and runs every test: the warnings-as-errors `dev` build,
# the AddressSanitizer + UndefinedBehaviorSanitizer `asan` build, and a bounded run of the
# protocol decoders' fuzzers.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install-deps.sh

for preset in dev asan; do
    echo "== $preset: configure, build, test"
    cmake --preset "$preset"
    cmake --build --preset "$preset"
    ctest --preset "$preset"
done
echo "== fuzz: the protocol decoders, 15 s each"
scripts/fuzz.sh 15
echo "All tests passed (dev, asan and fuzz)."
