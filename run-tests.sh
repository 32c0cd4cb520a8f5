#!/usr/bin/env bash
# Installs what SonarCarve needs, builds it with warnings as errors and runs every test
# (unit, e2e, gui, bench smoke, lint). Exits non-zero on any failure.
set -euo pipefail
cd "$(dirname "$0")"
./packaging/install-deps.sh
cmake --preset ci
cmake --build --preset ci --parallel "$(nproc)"
ctest --preset ci --parallel "$(nproc)"
