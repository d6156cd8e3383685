#!/usr/bin/env bash
# Installs what is needed, builds, and runs every test: the warnings-as-errors `dev` build,
# the AddressSanitizer + UndefinedBehaviorSanitizer `asan` build, and a bounded run of the
# fuzzers (the protocol decoders and the readers of the files users hand in).
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install-deps.sh

for preset in dev asan; do
    echo "== $preset: configure, build, test"
    cmake --preset "$preset"
    cmake --build --preset "$preset"
    ctest --preset "$preset"
done
echo "== fuzz: the protocol decoders and the file readers, 10 s each"
scripts/fuzz.sh 10
echo "All tests passed (dev, asan and fuzz)."
