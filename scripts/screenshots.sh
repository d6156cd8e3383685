#!/usr/bin/env bash
# Takes the screenshots in docs/images/ with the release build under Xvfb: the application
# running experiment f (light theme), the same in the dark theme with large text (the
# projector view), and experiment a (odometry only). Each run starts the embedded simulator
# at 5× real time and saves the window after the given number of seconds.
set -euo pipefail
cd "$(dirname "$0")/.."

cmake --preset release >/dev/null
cmake --build --preset release --target legofeup
mkdir -p docs/images
settings="$(mktemp -d)"
trap 'rm -rf "$settings"' EXIT

shot() {
    local file="$1" seconds="$2"
    shift 2
    rm -rf "$settings"/*
    XDG_CONFIG_HOME="$settings" xvfb-run -a -s "-screen 0 1600x1000x24" \
        build/release/app/legofeup --start --speed 5 --screenshot "docs/images/$file" \
        --screenshot-after "$seconds" "$@"
}

shot legofeup-lab.png 24 --experiment f --theme light
shot legofeup-lab-dark-large.png 24 --experiment f --theme dark --large-text
shot legofeup-lab-odometry-only.png 36 --experiment a --theme light
