#!/usr/bin/env bash
# Installs what SonarCarve needs, builds it and runs the main job on the bundled demo:
# simulate the riser inspection, reconstruct it in 3D, evaluate it against the ground truth
# and draw one of its frames. (Noise-free for now: denoising comes with the detector work.)
set -euo pipefail
cd "$(dirname "$0")"
./packaging/install-deps.sh
cmake --preset release
cmake --build --preset release --parallel "$(nproc)"
cli=./build/release/app/sonarcarve-cli
out=out/riser-demo
$cli simulate --scene riser --noise none --out "$out/mission" --force
$cli info "$out/mission"
$cli frame "$out/mission" --index 60 --polar "$out/frame60_polar.png" --fan "$out/frame60_fan.png"
$cli reconstruct "$out/mission" --out "$out/reconstruction"
echo
echo "Demo done. In $out:"
echo "  mission/                       the simulated mission (frames, navigation, ground truth)"
echo "  frame60_fan.png                one sonar frame drawn as its fan"
echo "  reconstruction/surface_points.ply   the 3D surface (x, y, z, intensity, views)"
echo "  reconstruction/map.bt          the carved map (open with octovis)"
echo "  reconstruction/report.json     timings and accuracy against the ground truth"
