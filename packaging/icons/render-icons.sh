#!/usr/bin/env bash
# Renders the PNG sizes of the application icon from sonarcarve.svg (librsvg2-bin's
# rsvg-convert). Run it after editing the SVG and commit the PNGs: the build installs them to
# the hicolor theme and compiles them into the GUI as its fallback icon, without needing rsvg.
set -euo pipefail
cd "$(dirname "$0")"
for size in 16 32 48 64 128 256; do
  rsvg-convert --width "$size" --height "$size" sonarcarve.svg --output "sonarcarve-$size.png"
done
