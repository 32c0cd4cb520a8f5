#!/usr/bin/env bash
# Writes the checksums tests/e2e/golden_outputs_test.cpp compares with: the same missions and
# runs, made with the CLI given.
#   make-golden.sh SONARCARVE_CLI > tests/data/golden/outputs.sha256
set -euo pipefail
cli=$(realpath "$1")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run() {  # case simulate-arguments...
  local name=$1
  shift
  "$cli" simulate "$@" --max-frames 30 --out "$work/$name/mission" >/dev/null
  "$cli" reconstruct "$work/$name/mission" --out "$work/$name/evicting" >/dev/null
  "$cli" reconstruct "$work/$name/mission" --save-map --out "$work/$name/whole-map" >/dev/null
}
run riser-noisy --scene riser --seed 7
run jacket-node --scene jacket-node --noise none
cd "$work"
for name in riser-noisy jacket-node; do
  for mode in evicting whole-map; do
    for file in surface_points.ply mesh.ply mesh.stl map.bt params.yaml map.scmap refined_nav.csv; do
      if [ -e "$name/$mode/$file" ]; then sha256sum "$name/$mode/$file"; fi
    done
  done
done
