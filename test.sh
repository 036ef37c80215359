#!/usr/bin/env bash
# Installs what is missing, configures, builds and runs every test (GUI tests under Xvfb). Non-zero on any failure.
# Benchmarks (CTest label `bench`) are not part of this run: `ctest --preset bench`.
set -euo pipefail
cd "$(dirname "$0")"
./scripts/install-deps.sh
cmake --preset default
cmake --build --preset default
xvfb-run -a -s "-screen 0 1600x1200x24" ctest --preset default "$@"
