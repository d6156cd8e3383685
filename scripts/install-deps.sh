#!/usr/bin/env bash
# Installs the Debian 12 packages LegoFeup Lab needs to build, test and run. Does nothing
# (and needs no network or root) when they are already installed. (*): needed only with the
# NXT (-DLEGOFEUP_WITH_NXT=ON, the default); a build configured with it OFF does without them.
set -euo pipefail

packages=(
    build-essential cmake ninja-build pkg-config clang-format
    libeigen3-dev                       # core: linear algebra
    libnanoflann-dev                    # core: kd-tree for ICP
    libbox2d-dev                        # sim: physics
    libtomlplusplus-dev nlohmann-json3-dev  # lessons: configuration files, summaries
    libyaml-cpp-dev                     # lessons: ROS map_server YAML map files
    libcli11-dev libcairo2-dev fonts-dejavu-core  # legofeup-cli: options, PNG/SVG plots
    libpango1.0-dev                     # report/: the student report's PDF (wrapped text)
    qt6-base-dev qt6-svg-dev libqcustomplot-dev  # ui/: the desktop application
    qt6-connectivity-dev                # ui/: Bluetooth scanning in the NXT connect dialog (*)
    xvfb xauth                          # scripts/screenshots.sh: the GUI on a virtual display
    libgtest-dev libgmock-dev           # tests
    libbenchmark-dev                    # bench/
    libbluetooth-dev                    # comms/: BlueZ RFCOMM sockets for bt: brick addresses (*)
    nbc                                 # tests: compile-check the NXC relay program
    clang lld libclang-rt-14-dev        # the dev and asan presets' compiler and linker; libFuzzer
    python3                             # examples/python and its test
)

missing=()
for package in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$package")
    fi
done

if [ ${#missing[@]} -eq 0 ]; then
    exit 0
fi

echo "Installing: ${missing[*]}"
as_root=()
if [ "$(id -u)" -ne 0 ]; then
    as_root=(sudo)
fi
"${as_root[@]}" apt-get update
DEBIAN_FRONTEND=noninteractive "${as_root[@]}" apt-get install -y --no-install-recommends "${missing[@]}"
