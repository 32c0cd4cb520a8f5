#!/usr/bin/env bash
# Installs what SonarCarve needs, builds it and runs the main job on the bundled demo.
# Today: simulate the riser demo (a vertical inspection with realistic noise), summarise it
# and draw one of its frames.
set -euo pipefail
cd "$(dirname "$0")"
./packaging/install-deps.sh
cmake --preset release
cmake --build --preset release --parallel "$(nproc)"
cli=./build/release/app/sonarcarve-cli
out=out/riser-demo
$cli simulate --scene riser --out "$out" --force
$cli info "$out"
$cli frame "$out" --index 60 --polar "$out/frame60_polar.png" --fan "$out/frame60_fan.png"
echo "demo mission in $out; pictures of frame 60: $out/frame60_fan.png"
