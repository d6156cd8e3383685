#!/usr/bin/env bash
# Installs what is needed, builds, and runs every test once: the `dev` build (clang, debug,
# warnings as errors) builds and runs the GUI's tests; the `asan` build (clang, AddressSanitizer +
# UndefinedBehaviorSanitizer) runs every other test; the real-time link tests run beside the
# others (they wait rather than compute). Before running,
# it checks that the two lists together are the whole suite, so no test is left out. Each
# phase prints how long it took, so a slow step shows where it is.
set -euo pipefail
cd "$(dirname "$0")/.."

phase_start=$SECONDS
phase() {
    echo "== $1 ($((SECONDS - phase_start)) s so far)"
}

phase "install the Debian packages"
scripts/install-deps.sh

# dev builds only what the GUI's tests need (target legofeup_gui_tests): its other test
# programs would be built twice, as asan builds and runs them.
phase "dev: configure and build the GUI's tests"
cmake --preset dev
cmake --build --preset dev --target legofeup_gui_tests
phase "asan: configure and build"
cmake --preset asan
cmake --build --preset asan

phase "check that the GUI's tests (dev) and the others (asan) are the whole suite"
scripts/check-test-split.sh

phase "dev: the GUI's tests"
ctest --preset dev --label-regex '^gui$'
phase "asan: every other test, under the sanitizers"
# The real-time tests (label realtime: a lap of experiment f through the emulated NXT, in
# real time) mostly wait on the link, so they run beside the others, which keep the two
# cores; their output follows the others'.
mkdir -p build
ctest --preset asan --label-regex '^realtime$' --parallel 4 >build/asan-realtime.log 2>&1 &
realtime=$!
status=0
ctest --preset asan --label-exclude '^realtime$' 2>&1 | tee build/asan-tests.log || status=$?
realtime_status=0
wait "$realtime" || realtime_status=$?
echo "-- the real-time tests:"
cat build/asan-realtime.log
if [[ $status -ne 0 || $realtime_status -ne 0 ]]; then
    echo "asan: tests failed (above)." >&2
    exit 1
fi
phase "done"
echo "All tests passed (the GUI's in dev, the others in asan) in $((SECONDS - phase_start)) s."
echo "The fuzzers are not tests of the suite: scripts/fuzz.sh builds and runs them (CI does)."
