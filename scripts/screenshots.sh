#!/usr/bin/env bash
# Regenerates every picture in docs/images/ from the program as it is today, with the release
# build: `legofeup` itself under Xvfb for what its command line can show, and the GUI tests
# that drive the window (tests/ui, LEGOFEUP_SCREENSHOTS) for what needs driving. Prints each
# file it wrote and fails if a picture was not written or is empty.
#
#   scripts/screenshots.sh                    # every picture
#   scripts/screenshots.sh laser-lesson.png   # only these
#
# Deterministic: each picture from a fresh settings directory (the preferences below only),
# the lessons' fixed seeds, a 1600 × 1000 virtual screen (the window at its default size),
# and the run's pictures taken at a run time (--screenshot-at), not after a wall-clock wait.
set -euo pipefail
cd "$(dirname "$0")/.."

# The pictures, one a line: the file in docs/images/, what makes it, and how.
#   FILE app PREFERENCES ARGS…  legofeup ARGS… --screenshot under Xvfb (the light theme unless
#       ARGS give one), its settings directory holding only PREFERENCES: comma-separated
#       group/key=value of ui/include/legofeup/ui/window/app_settings.hpp, or - for none.
#       view/plotTab: 0 Estimate, 1 Commands & sensors, 2 Consistency, 3 Beacons & filters,
#       4 Heading & speed sensors, 5 Laser scan matching, 6 Particle filter; view/plotWindow: seconds, 0 the
#       whole run; link/kind=2 with nxt/emulated=true: the emulated brick.
#   FILE test PROGRAM FUNCTION  the QtTest PROGRAM's test FUNCTION, which saves FILE.
# tests/docs/check_doc_images.cmake reads this table: the pictures the docs show are exactly
# these, and docs/images/ holds nothing else.
readonly PICTURES='
legofeup-lab.png               app -                                --experiment f --speed 5 --start --screenshot-at 120
legofeup-lab-dark-large.png    app -                                --experiment f --speed 5 --start --screenshot-at 120 --theme dark --large-text
legofeup-lab-odometry-only.png app -                                --experiment a --speed 5 --start --screenshot-at 160
nxt-rehearsal.png              app link/kind=2,nxt/emulated=true    --experiment f --start --screenshot-at 15
beacons-lesson.png             app -                                --experiment beacons:a --speed 5 --start --screenshot-after 45
beacons-ekf-ukf.png            app view/plotTab=3,view/plotWindow=0 --experiment beacons:a --speed 5 --start --screenshot-at 52
heading-sensors.png            app view/plotTab=4,view/plotWindow=0 --experiment compass:c --speed 5 --start --screenshot-at 100
laser-lesson.png               app view/plotTab=5                   --experiment laser:a --speed 2 --start --screenshot-at 60
laser-twin-hall.png            app -                                --experiment laser:c --speed 2 --start --screenshot-at 45
laser-far-kidnap.png           app -                                --experiment laser:d --speed 2 --start --screenshot-at 53
mcl-global.png                 app view/plotTab=6,view/plotWindow=0 --experiment mcl:a --speed 1 --start --screenshot-at 1.2
nxt-connect.png                test ui_connect_dialog_test scanningWithoutBlueZSaysSoAtOnceAndReturns
lesson-panel.png               test ui_lesson_panel_test theConclusionIsHiddenUntilTheRunFinishesThenShownWithTheRunsOwnNumbers
refilter.png                   test ui_refilter_dialog_test changingQGivesASecondEstimateOnTheSameReadings
ir-calibration.png             test ui_calibration_dialogs_test rowsThatSayTheirSensorGiveItsOwnCurve
umbmark.png                    test ui_calibration_dialogs_test umbmarkIsTheLibrarysAndIsSavedIntoTheProfile
'

build=build/release
images=docs/images
screen="-screen 0 1600x1000x24"

wanted=("$@")
is_wanted() {
    [ ${#wanted[@]} -eq 0 ] && return 0
    local name
    for name in "${wanted[@]}"; do
        [ "$name" = "$1" ] && return 0
    done
    return 1
}

rows=()
targets=()
while read -r file maker rest; do
    [ -z "$file" ] && continue
    is_wanted "$file" || continue
    rows+=("$file $maker $rest")
    if [ "$maker" = app ]; then
        targets+=(legofeup)
    else
        targets+=("${rest%% *}")
    fi
done <<<"$PICTURES"
for name in "${wanted[@]}"; do
    grep -q "^$name " <<<"$PICTURES" || { echo "screenshots.sh: no picture $name" >&2; exit 2; }
done

cmake --preset release >/dev/null
# Two jobs unless told otherwise: the build is long and the machine may be shared.
mapfile -t targets < <(printf '%s\n' "${targets[@]}" | sort -u)
cmake --build "$build" --parallel "${CMAKE_BUILD_PARALLEL_LEVEL:-2}" --target "${targets[@]}"
mkdir -p "$images"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# A fresh settings directory holding only PREFERENCES (group/key=value,…; - for none), in
# QSettings' INI format: one [group] with its keys.
fresh_settings() {
    rm -rf "$work/settings"
    mkdir -p "$work/settings/LegoFeup"
    local conf="$work/settings/LegoFeup/LegoFeup Lab.conf" group
    : >"$conf"
    [ "$1" = - ] && return 0
    local entries
    entries="$(tr , '\n' <<<"$1")"
    cut -d/ -f1 <<<"$entries" | sort -u | while read -r group; do
        echo "[$group]"
        grep "^$group/" <<<"$entries" | cut -d/ -f2-
    done >>"$conf"
}

# legofeup ARGS…, saving FILE into $work/out.
from_app() {
    local file="$1" preferences="$2"
    shift 2
    fresh_settings "$preferences"
    local theme=(--theme light)
    [[ " $* " == *" --theme "* ]] && theme=()
    XDG_CONFIG_HOME="$work/settings" xvfb-run -a -s "$screen" \
        "$build/app/legofeup" "${theme[@]}" "$@" --screenshot "$work/out/$file"
}

# The QtTest PROGRAM's FUNCTION, keeping the picture FILE it saves into $work/out.
from_test() {
    local program="$2" function="$3"
    rm -rf "$work/settings" && mkdir -p "$work/settings"
    XDG_CONFIG_HOME="$work/settings" LEGOFEUP_SCREENSHOTS="$work/out" \
        LEGOFEUP_SETTINGS_SCOPE=test QT_QPA_PLATFORM=offscreen \
        "$build/tests/ui/$program" "$function"
}

# "WIDTH × HEIGHT" of a PNG, from its header.
png_size() {
    od -An -tu1 -j16 -N8 "$1" |
        awk '{ printf "%d × %d", (($1*256+$2)*256+$3)*256+$4, (($5*256+$6)*256+$7)*256+$8 }'
}

failed=()
for row in "${rows[@]}"; do
    read -r file maker rest <<<"$row"
    echo "== $file: $maker $rest" >&2
    rm -rf "$work/out" && mkdir -p "$work/out"
    # shellcheck disable=SC2086 # the table's arguments are words
    if [ "$maker" = app ]; then
        from_app "$file" $rest >&2 || true
    else
        from_test "$file" $rest >&2 || true
    fi
    if [ -s "$work/out/$file" ]; then
        mv "$work/out/$file" "$images/$file"
        echo "wrote $images/$file ($(png_size "$images/$file"), $(stat -c %s "$images/$file") bytes)"
    else
        echo "screenshots.sh: $file was not written (docs/images keeps the old one)" >&2
        failed+=("$file")
    fi
done
if [ ${#failed[@]} -gt 0 ]; then
    echo "screenshots.sh: ${#failed[@]} picture(s) not written: ${failed[*]}" >&2
    exit 1
fi
