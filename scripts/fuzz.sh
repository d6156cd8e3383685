#!/usr/bin/env bash
# Builds the libFuzzer targets (in the `fuzz` preset's tree, build/fuzz-tree: clang, ASan +
# UBSan, coverage instrumentation) — the UDP protocol's decoders, the NXT codec and the readers of the files
# users hand in — and runs each for a bounded time, two at a time (one per core).
# Usage: scripts/fuzz.sh [seconds per target]
# Each starts from its seeds in fuzz/corpus/<target>/ (when there are any; what it finds
# goes to build/fuzz/corpus/<target>/) with the options CMake wrote beside it
# (<target>.options: its -max_len). An input slower than 10 s counts as a hang.
# A crash leaves its input in build/fuzz/artifacts/ and fails the script; each target's
# output is in build/fuzz/<target>.log.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-15}"
if ! [[ "$seconds" =~ ^[1-9][0-9]*$ ]]; then
    echo "scripts/fuzz.sh: the seconds per target must be a whole number above 0, not '$seconds'" >&2
    exit 2
fi
parallel=2

cmake --preset fuzz
cmake --build --preset fuzz
mkdir -p build/fuzz/artifacts

# Runs one fuzzer; its status is its exit status, what it printed is in its log.
fuzz_one() {
    local fuzzer="$1" name corpora=() options=()
    name="$(basename "$fuzzer")"
    if [[ -d "fuzz/corpus/$name" ]]; then
        mkdir -p "build/fuzz/corpus/$name"
        corpora=("build/fuzz/corpus/$name" "fuzz/corpus/$name") # libFuzzer adds to the first
    fi
    if [[ -f "$fuzzer.options" ]]; then
        read -r -a options <"$fuzzer.options"
    fi
    "$fuzzer" "${options[@]}" -max_total_time="$seconds" -timeout=10 -print_final_stats=1 \
        -artifact_prefix="build/fuzz/artifacts/$name-" "${corpora[@]}" >"build/fuzz/$name.log" 2>&1
}

# What a finished fuzzer reports; fails (after saying why) if it failed or left an input.
report() {
    local name="$1" status="$2" log="build/fuzz/$1.log"
    echo "== $name: ${seconds} s, exit status $status"
    grep -E "stat::number_of_executed_units|stat::average_exec_per_sec|ERROR|SUMMARY" "$log" || true
    if [[ $status -ne 0 ]] || ls build/fuzz/artifacts/"$name"-* >/dev/null 2>&1; then
        echo "$name failed (exit status $status; its output: $log):" >&2
        ls build/fuzz/artifacts/"$name"-* 2>/dev/null >&2 || true
        return 1
    fi
}

fuzzers=()
for fuzzer in build/fuzz-tree/fuzz/fuzz_*; do
    [[ -f "$fuzzer" && -x "$fuzzer" ]] && fuzzers+=("$fuzzer") # skip the .options files
done
if [[ ${#fuzzers[@]} -eq 0 ]]; then
    echo "scripts/fuzz.sh: no fuzzer was built in build/fuzz-tree/fuzz" >&2
    exit 1
fi

declare -A running=() # pid -> name
failed=0
# Waits for one running fuzzer to end and reports it.
reap_one() {
    local status=0 done_pid
    wait -n -p done_pid "${!running[@]}" || status=$?
    report "${running[$done_pid]}" "$status" || failed=1
    unset "running[$done_pid]"
}
for fuzzer in "${fuzzers[@]}"; do
    fuzz_one "$fuzzer" &
    running[$!]="$(basename "$fuzzer")"
    if [[ ${#running[@]} -ge $parallel ]]; then
        reap_one
    fi
done
while [[ ${#running[@]} -gt 0 ]]; do
    reap_one
done
if [[ $failed -ne 0 ]]; then
    echo "Fuzzing failed: see the messages above." >&2
    exit 1
fi
echo "Fuzzing passed: ${#fuzzers[@]} fuzzers, ${seconds} s each."
