#!/usr/bin/env bash
# Builds the libFuzzer targets (the `fuzz` preset: clang, ASan + UBSan) — the UDP protocol's
# decoders, the NXT codec and the readers of the files users hand in — and runs each for a
# bounded time. Usage: scripts/fuzz.sh [seconds per target]
# Each starts from its seeds in fuzz/corpus/<target>/ (when there are any; what it finds
# goes to build/fuzz/corpus/<target>/) with the options CMake wrote beside it
# (<target>.options: its -max_len). An input slower than 10 s counts as a hang.
# A crash leaves its input in build/fuzz/artifacts/ and fails the script; each target's
# output is in build/fuzz/<target>.log.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-15}"

cmake --preset fuzz
cmake --build --preset fuzz
mkdir -p build/fuzz/artifacts
for fuzzer in build/fuzz/fuzz/fuzz_*; do
    [[ -f "$fuzzer" && -x "$fuzzer" ]] || continue # skip the .options files
    name="$(basename "$fuzzer")"
    corpora=()
    if [[ -d "fuzz/corpus/$name" ]]; then
        mkdir -p "build/fuzz/corpus/$name"
        corpora=("build/fuzz/corpus/$name" "fuzz/corpus/$name") # libFuzzer adds to the first
    fi
    options=()
    if [[ -f "$fuzzer.options" ]]; then
        read -r -a options <"$fuzzer.options"
    fi
    echo "== $name: ${seconds} s ${options[*]}"
    log="build/fuzz/$name.log"
    status=0
    "$fuzzer" "${options[@]}" -max_total_time="$seconds" -timeout=10 -print_final_stats=1 \
        -artifact_prefix="build/fuzz/artifacts/$name-" "${corpora[@]}" >"$log" 2>&1 || status=$?
    grep -E "stat::number_of_executed_units|stat::average_exec_per_sec|ERROR|SUMMARY" "$log" || true
    if [[ $status -ne 0 ]] || ls build/fuzz/artifacts/"$name"-* >/dev/null 2>&1; then
        echo "$name failed (exit status $status; its output: $log):" >&2
        ls build/fuzz/artifacts/"$name"-* 2>/dev/null >&2 || true
        exit 1
    fi
done
echo "Fuzzing passed."
