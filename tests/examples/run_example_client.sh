#!/usr/bin/env bash
# Runs an example client (examples/python/drive_square.py or examples/octave/drive_square.m)
# against a fresh legofeup-sim and checks its summary line: one lap finished, about one
# lap's distance driven (the 2 m square: 8 m), and the robot really (ground truth) back
# near its start (-1, -1).
#
# Usage: run_example_client.sh PATH/TO/legofeup-sim REPOSITORY_ROOT python|octave
# The interpreters are $PYTHON (ctest sets it, else python3) and $OCTAVE (else octave).
set -euo pipefail

if [[ $# -ne 3 || ( $3 != python && $3 != octave ) ]]; then
    echo "usage: $0 PATH/TO/legofeup-sim REPOSITORY_ROOT python|octave" >&2
    exit 2
fi
sim=$1
root=$2
client=$3
python=${PYTHON:-python3}
octave=${OCTAVE:-octave}

# Bounds. Odometry alone drives the error-free default robot back to within a few mm of
# its start; 0.35 m leaves room for physics changes without hiding a broken client.
min_distance=7
max_distance=9.5
max_end_error=0.35

tmp=$(mktemp -d)
server_pid=""
cleanup() {
    if [[ -n $server_pid ]]; then
        kill "$server_pid" 2>/dev/null || true
        wait "$server_pid" 2>/dev/null || true
    fi
    rm -rf "$tmp"
}
trap cleanup EXIT

fail() {
    echo "FAILED: $*" >&2
    if [[ -s $tmp/server.log ]]; then
        echo "--- legofeup-sim output:" >&2
        cat "$tmp/server.log" >&2
    fi
    exit 1
}

# Python keeps up with 20× real time even on a loaded machine; Octave (about 1.5 ms per
# frame) does not, so it runs in lockstep, which keeps the result independent of the load.
time_scale=20
if [[ $client == octave ]]; then
    time_scale=0
fi
# --duration stops the server on its own should this script be killed before its trap runs.
"$sim" --port 0 --ready-file "$tmp/ready" --time-scale "$time_scale" --seed 7 --duration 110 \
    >"$tmp/server.log" 2>&1 &
server_pid=$!

# The server writes the ready file (robot=, truth=, control= lines) once it listens.
for _ in $(seq 100); do
    if grep -q '^control=' "$tmp/ready" 2>/dev/null; then
        break
    fi
    kill -0 "$server_pid" 2>/dev/null || fail "legofeup-sim exited before it was ready"
    sleep 0.1
done
grep -q '^control=' "$tmp/ready" 2>/dev/null || fail "no ready file from legofeup-sim after 10 s"

port() {
    sed -n "s/^$1=\([0-9][0-9]*\)$/\1/p" "$tmp/ready"
}
robot_port=$(port robot)
truth_port=$(port truth)
control_port=$(port control)
[[ -n $robot_port && -n $truth_port && -n $control_port ]] ||
    fail "unreadable ready file: $(cat "$tmp/ready")"
echo "legofeup-sim ready: robot=$robot_port truth=$truth_port control=$control_port"

status=0
if [[ $client == python ]]; then
    # No bytecode caches in the source tree.
    output=$(PYTHONDONTWRITEBYTECODE=1 "$python" "$root/examples/python/drive_square.py" \
        --port "$robot_port" --truth-port "$truth_port" --control-port "$control_port" \
        --laps 1 --quiet --seed 7 2>&1) || status=$?
else
    output=$(cd "$root/examples/octave" && "$octave" --no-gui --quiet --no-history --eval \
        "drive_square ('port', $robot_port, 'truth_port', $truth_port, 'control_port', $control_port, 'laps', 1, 'quiet', true, 'seed', 7)" \
        2>&1) || status=$?
fi
echo "$output"
[[ $status -eq 0 ]] || fail "the $client client exited with status $status"

number='-?[0-9]+(\.[0-9]+)?'
pattern="^finished: laps=([0-9]+) frames=([0-9]+) missing=([0-9]+) odometry=\(($number), ($number), ($number)\) truth=\(($number), ($number), ($number)\) distance_driven=($number) m$"
summary=$(grep '^finished:' <<<"$output") || fail "no summary line (finished: ...)"
[[ $summary =~ $pattern ]] || fail "unreadable summary line: $summary"
laps=${BASH_REMATCH[1]}
frames=${BASH_REMATCH[2]}
missing=${BASH_REMATCH[3]}
truth_x=${BASH_REMATCH[10]}
truth_y=${BASH_REMATCH[12]}
distance=${BASH_REMATCH[16]}

[[ $laps -eq 1 ]] || fail "laps=$laps, expected 1"
echo "ok: the lap finished (laps=$laps, $frames frames, $missing missing)"

awk -v d="$distance" -v lo="$min_distance" -v hi="$max_distance" \
    'BEGIN { exit !(d >= lo && d <= hi) }' ||
    fail "distance_driven=$distance m, expected $min_distance … $max_distance m"
echo "ok: distance driven $distance m is within $min_distance … $max_distance m"

end_error=$(awk -v x="$truth_x" -v y="$truth_y" \
    'BEGIN { printf "%.3f", sqrt((x + 1) ^ 2 + (y + 1) ^ 2) }')
awk -v e="$end_error" -v bound="$max_end_error" 'BEGIN { exit !(e <= bound) }' ||
    fail "the robot ended at ($truth_x, $truth_y), $end_error m from the start (-1, -1); bound $max_end_error m"
echo "ok: the robot ended at ($truth_x, $truth_y) (ground truth), $end_error m from the start (-1, -1); bound $max_end_error m"
