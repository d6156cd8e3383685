#!/usr/bin/env bash
# Builds the libFuzzer targets of the UDP protocol's decoders (the `fuzz` preset: clang,
# ASan + UBSan) and runs each for a bounded time. Usage: scripts/fuzz.sh [seconds per target]
# A crash leaves its input in build/fuzz/artifacts/ and fails the script.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-15}"

cmake --preset fuzz
cmake --build --preset fuzz
mkdir -p build/fuzz/artifacts
for fuzzer in build/fuzz/fuzz/fuzz_*; do
    name="$(basename "$fuzzer")"
    echo "== $name: ${seconds} s"
    # -max_len above the largest packet, so oversized inputs are tried too.
    "$fuzzer" -max_total_time="$seconds" -max_len=2400 -print_final_stats=1 \
        -artifact_prefix="build/fuzz/artifacts/$name-" 2>&1 | grep -E "stat::number_of_executed_units|ERROR|SUMMARY" || true
    if ls build/fuzz/artifacts/"$name"-* >/dev/null 2>&1; then
        echo "$name found a failing input: build/fuzz/artifacts/$name-*" >&2
        exit 1
    fi
done
echo "Fuzzing passed."
