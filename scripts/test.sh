#!/usr/bin/env bash
# Installs what is needed, builds, and runs every test: the warnings-as-errors `dev` build
# and the AddressSanitizer + UndefinedBehaviorSanitizer `asan` build.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install-deps.sh

for preset in dev asan; do
    echo "== $preset: configure, build, test"
    cmake --preset "$preset"
    cmake --build --preset "$preset"
    ctest --preset "$preset"
done
echo "All tests passed (dev and asan)."
