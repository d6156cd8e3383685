#!/usr/bin/env bash
# Checks that scripts/test.sh runs every test of the suite exactly once: the dev build's
# tests labelled `gui` there, and all the asan build's tests (which has no GUI) — together
# exactly the dev build's whole list, with none in both. Needs both configured, the asan
# build built, and in dev at least the GUI's tests (target legofeup_gui_tests).
#
# A GoogleTest program dev did not build is listed there only as `<program>_NOT_BUILT`
# (gtest_discover_tests lists a program's tests once it is built): it counts as run when the
# asan build runs tests of that program.
set -euo pipefail
cd "$(dirname "$0")/.."

ctest --preset dev --show-only=json-v1 >build/tests-dev.json
ctest --preset dev --label-regex '^gui$' --show-only=json-v1 >build/tests-dev-gui.json
ctest --preset asan --show-only=json-v1 >build/tests-asan.json

python3 - build/tests-dev.json build/tests-dev-gui.json build/tests-asan.json <<'EOF'
import json
import os
import sys

def tests(path):
    return json.load(open(path))["tests"]

dev, gui, asan = (tests(path) for path in sys.argv[1:4])
gui_names = {t["name"] for t in gui}
asan_names = {t["name"] for t in asan}
# The programs the asan build runs tests of (a test's command starts with its program).
asan_programs = {os.path.basename(t["command"][0]) for t in asan if t.get("command")}
not_built = "_NOT_BUILT"

problems = []
both = sorted(gui_names & asan_names)
if both:
    problems.append(("Labelled gui but also in the asan build (give them no gui label):", both))
unbuilt_gui = sorted(n for n in gui_names if n.endswith(not_built))
if unbuilt_gui:
    problems.append(("GUI test programs dev did not build (add them to legofeup_gui_tests):",
                     unbuilt_gui))
missing = []
for name in sorted(t["name"] for t in dev):
    if name in gui_names or name in asan_names:
        continue
    if name.endswith(not_built) and name[: -len(not_built)] in asan_programs:
        continue  # built and run in asan instead
    missing.append(name)
if missing:
    problems.append(("In the dev build but neither labelled gui nor in the asan build "
                     "(label them gui):", missing))
dev_names = {t["name"] for t in dev}
dev_unbuilt = {n[: -len(not_built)] for n in dev_names if n.endswith(not_built)}
unknown = sorted(t["name"] for t in asan
                 if t["name"] not in dev_names
                 and not (t.get("command")
                          and os.path.basename(t["command"][0]) in dev_unbuilt))
if unknown:
    problems.append(("In the asan build but not in the dev build:", unknown))

for heading, names in problems:
    print(heading, file=sys.stderr)
    for name in names:
        print(name, file=sys.stderr)
if problems:
    sys.exit(1)
print(f"The suite: {len(gui_names)} tests of the GUI in dev and {len(asan_names)} in asan.")
EOF
