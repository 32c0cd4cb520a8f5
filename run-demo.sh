#!/usr/bin/env bash
# Installs what SonarCarve needs, builds it and runs the main job on the bundled demo.
# Today that is `sonarcarve-cli info` on the example mission shipped in resources/.
set -euo pipefail
cd "$(dirname "$0")"
./packaging/install-deps.sh
cmake --preset release
cmake --build --preset release --parallel "$(nproc)"
./build/release/app/sonarcarve-cli info resources/example_mission
