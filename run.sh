#!/usr/bin/env bash
# Installs what is missing, configures, builds, and starts the VascuSim workstation on the built-in demo study.
# Extra arguments go to `vascusim` (e.g. a study folder instead of the demo: ./run.sh path/to/study.vsim).
set -euo pipefail
cd "$(dirname "$0")"
./scripts/install-deps.sh
cmake --preset default
cmake --build --preset default --target vascusim vascusim-cli
# The demo study is the full-size aaa CT phantom, written through the DICOM import on first use (a few seconds).
./build/default/bin/vascusim-cli demo-study
if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
    echo "run.sh: no display found; starting under a virtual X server (xvfb-run). Headless use: build/default/bin/vascusim-cli" >&2
    exec xvfb-run -a -s "-screen 0 1600x1200x24" ./build/default/bin/vascusim "${@:---demo}"
fi
exec ./build/default/bin/vascusim "${@:---demo}"
