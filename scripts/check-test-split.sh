#!/usr/bin/env bash
# Checks that scripts/test.sh runs every test of the suite exactly once: the dev build's
# tests labelled `gui` there, and all the asan build's tests (which has no GUI) — together
# exactly the dev build's whole list, with none in both. Needs both built.
set -euo pipefail
cd "$(dirname "$0")/.."

names() { # the test names `ctest --show-only` lists for the given arguments, sorted
    ctest "$@" --show-only | sed -n 's/^ *Test *#[0-9]*: //p' | sort
}
all="$(names --preset dev)"
gui="$(names --preset dev --label-regex '^gui$')"
asan="$(names --preset asan)"

both="$(comm -12 <(echo "$gui") <(echo "$asan"))"
missing="$(comm -23 <(echo "$all") <(sort <(echo "$gui") <(echo "$asan")))"
unknown="$(comm -13 <(echo "$all") <(echo "$asan"))"
status=0
if [[ -n "$both" ]]; then
    echo "Labelled gui but also in the asan build (give them no gui label):" >&2
    echo "$both" >&2
    status=1
fi
if [[ -n "$missing" ]]; then
    echo "In the dev build but neither labelled gui nor in the asan build (label them gui):" >&2
    echo "$missing" >&2
    status=1
fi
if [[ -n "$unknown" ]]; then
    echo "In the asan build but not in the dev build:" >&2
    echo "$unknown" >&2
    status=1
fi
[[ $status -eq 0 ]] && echo "The suite: $(echo "$all" | wc -l) tests, $(echo "$gui" | wc -l) of the GUI in dev and $(echo "$asan" | wc -l) in asan."
exit $status
