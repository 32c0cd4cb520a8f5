#!/usr/bin/env bash
# Installs what SonarCarve needs, builds it and runs the main job on the bundled demo:
# simulate the riser inspection (with realistic noise) and a run in empty water, learn the
# noise model, reconstruct the riser in 3D, evaluate it against the ground truth and draw
# one of its frames before and after denoising. Where there is a display, the workbench then
# opens on the demo mission and carves it live (SONARCARVE_NO_GUI=1 skips it).
set -euo pipefail
cd "$(dirname "$0")"
./packaging/install-deps.sh
cmake --preset release
cmake --build --preset release --parallel "$(nproc)"
cli=./build/release/app/sonarcarve-cli
out=out/riser-demo
$cli simulate --scene riser --out "$out/mission" --force
$cli simulate --scene riser --empty-water --seed 99 --out "$out/empty-water" --force
$cli noise-model "$out/empty-water" --out "$out/noise.yaml"
$cli info "$out/mission"
$cli frame "$out/mission" --index 60 --polar "$out/frame60_polar.png" --fan "$out/frame60_fan.png" \
  --noise-model "$out/noise.yaml" --detected "$out/frame60_denoised.png"
$cli reconstruct "$out/mission" --noise-model "$out/noise.yaml" --out "$out/reconstruction"
echo
echo "Demo done. In $out:"
echo "  mission/                       the simulated mission (frames, navigation, ground truth)"
echo "  noise.yaml                     the noise model learned from empty-water frames"
echo "  frame60_fan.png                one sonar frame drawn as its fan (and _polar, _denoised)"
echo "  reconstruction/surface_points.ply   the 3D surface (x, y, z, intensity, views)"
echo "  reconstruction/mesh.ply, mesh.stl   its mesh (world NED frame, metres)"
echo "  reconstruction/map.bt          the carved map (open with octovis)"
echo "  reconstruction/report.json     timings and accuracy against the ground truth"

if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ] && [ -z "${SONARCARVE_NO_GUI:-}" ]; then
  echo
  echo "Opening the workbench on the demo mission (close its window to finish)..."
  # VTK on Debian 12 draws through GLX: under Wayland, Qt must use XWayland.
  QT_QPA_PLATFORM="${QT_QPA_PLATFORM:-xcb}" ./build/release/app/sonarcarve "$out/mission" \
    --noise-model "$out/noise.yaml"
else
  echo
  echo "No display: the reconstruction above ran headless. With a display, run"
  echo "  ./build/release/app/sonarcarve $out/mission --noise-model $out/noise.yaml"
fi
