#!/usr/bin/env bash
# make-screenshots.sh BUILD_DIR [OUT_DIR]: the user guide's pictures (docs/images/guide_*.png),
# made from the current programs under Xvfb. Needs the sonarcarve package installed (the first
# part starts the workbench from the desktop menu, as an analyst would) and, besides
# install-deps.sh's packages: apt-get install icewm xdotool imagemagick. Takes about 15
# minutes on 2 cores.
#   part 1, getting started: IceWM's menu with the installed desktop entry and its icon, then
#     the workbench driven with xdotool: open the demo mission, set the noise model, watch the
#     map grow, colour by error, the Export menu;
#   part 2, parameters: the workbench's --screenshot at several values of a parameter,
#     cropped to the denoised fan and the 3D view and put side by side;
#   part 3, troubleshooting: an orbit of the riser with its navigation made wrong on purpose.
set -euo pipefail
build=$(cd "$1" && pwd)
out=$(mkdir -p "${2:-$(dirname "$0")/../../docs/images}" && cd "${2:-$(dirname "$0")/../../docs/images}" && pwd)
cli=$build/app/sonarcarve-cli
gui=$build/app/sonarcarve
for tool in Xvfb icewm xdotool import montage convert /usr/bin/sonarcarve; do
  command -v "$tool" >/dev/null || { echo "missing: $tool" >&2; exit 1; }
done
work=${WORK:-/tmp/sonarcarve-guide}
mkdir -p "$work"
cd "$work"

# The data: the README's demo (riser, vertical dive, noisy) and an orbit of the riser.
if [ ! -f riser-demo/noise.yaml ]; then
  "$cli" simulate --scene riser --out riser-demo/mission --force
  "$cli" simulate --scene riser --empty-water --seed 99 --out riser-demo/empty-water --force
  "$cli" noise-model riser-demo/empty-water --out riser-demo/noise.yaml
  "$cli" noise-model riser-demo/empty-water --smoothing 1 --out riser-demo/noise-smoothing1.yaml
fi
if [ ! -f orbit/noise.yaml ]; then
  "$cli" simulate --scene riser --trajectory orbit --out orbit/mission --force
  "$cli" simulate --scene riser --trajectory orbit --empty-water --seed 99 --out orbit/empty-water \
    --force
  "$cli" noise-model orbit/empty-water --out orbit/noise.yaml
fi

# ---- Part 1: getting started, on a desktop (IceWM) with the installed package.
# (SKIP_DESKTOP=1 skips it, to make the other pictures again.)
if [ -z "${SKIP_DESKTOP:-}" ]; then
display=:$((90 + RANDOM % 9))
Xvfb "$display" -screen 0 1280x800x24 -nolisten tcp >"$work/xvfb.log" 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null || true' EXIT
export DISPLAY=$display
sleep 2
(cd "$work/riser-demo" && exec icewm) >"$work/icewm.log" 2>&1 &
sleep 4
shot() { import -window root "$out/$1"; }
# A run is over when the progress bar's right end (bottom right) turns the highlight blue.
wait_done() {
  for _ in $(seq 1 240); do
    sleep 1
    colour=$(import -window root -crop 1x1+1250+760 -depth 8 txt:- | grep -o '#[0-9A-F]\{6\}')
    [ "$colour" = "#359BDB" ] && { sleep 3; return; }
  done
  echo "the run did not finish" >&2
  exit 1
}
xdotool key ctrl+Escape && sleep 1 && xdotool key s && sleep 1 && xdotool key g && sleep 1.5
shot guide_launcher.png
xdotool key Return && sleep 8                                 # starts /usr/bin/sonarcarve
shot guide_start.png
# Magnified twice: the menu entry, and the window's taskbar button and title bar icon.
convert \( "$out/guide_launcher.png" -crop 435x48+0+588 +repage \) \
  \( "$out/guide_start.png" -crop 290x24+258+776 +repage \) \
  \( "$out/guide_start.png" -crop 60x20+0+0 +repage \) -filter point -resize 200% \
  -background white -gravity North -splice 0x12 -gravity West -append \
  "$out/guide_launcher_zoom.png"
xdotool key alt+f && sleep 1
shot guide_file_menu.png
xdotool key Return && sleep 2 && xdotool type --delay 30 "$work/riser-demo/mission" && sleep 1
shot guide_open_dialog.png
xdotool key Return && sleep 8                                 # the model learned, the fan denoised
shot guide_opened_no_noise_model.png
xdotool mousemove 233 260 click 1 && sleep 2                  # Noise model: "…"
xdotool type --delay 30 "$work/riser-demo/noise.yaml" && sleep 1 && xdotool key Return
sleep 6
shot guide_carving.png
wait_done
shot guide_first_map.png
xdotool mousemove 540 56 click 1 && sleep 1 && xdotool key Down Down Return && sleep 3
shot guide_colour_by_error.png
xdotool key alt+f && sleep 1 && xdotool key Up Up Right && sleep 1
shot guide_export_menu.png
xdotool key Escape Escape Escape
kill $xvfb
wait $xvfb 2>/dev/null || true
unset DISPLAY
fi

# ---- Part 2: parameters. One run of the workbench per value, at frame 60, coloured by error.
# (REUSE=1 keeps the screenshots of an earlier call, to lay the pictures out again.)
run() { # run NAME MISSION NOISE_MODEL PARAMS_YAML
  [ -n "${REUSE:-}" ] && [ -f "$work/$1.png" ] && return
  printf '%s\n' "$4" >"$work/$1.yaml"
  QT_QPA_PLATFORM=xcb xvfb-run -a -s '-screen 0 1280x800x24' "$gui" "$2" --noise-model "$3" \
    --params "$work/$1.yaml" --frame 60 --colour-by error --quit-when-done \
    --screenshot "$work/$1.png" >"$work/$1.log" 2>&1
}
# The denoised fan and the 3D view in the 1280 x 800 window.
fan() { convert "$work/$1.png" -crop 586x226+290+289 +repage "$work/$1_fan.png"; }
map() { convert "$work/$1.png" -crop 400x489+880+58 +repage "$work/$1_map.png"; }
side_by_side() { # side_by_side OUT COLUMNS "LABEL|NAME"...: rows of COLUMNS labelled pictures
  local target=$1 columns=$2 rows=() i
  shift 2
  while [ $# -gt 0 ]; do
    local args=()
    for ((i = 0; i < columns && $# > 0; ++i)); do
      args+=(-label "${1%%|*}" "$work/${1#*|}")
      shift
    done
    montage "${args[@]}" -tile "${columns}x1" -geometry +6+6 -pointsize 20 -background white \
      "$work/row${#rows[@]}.png"
    rows+=("$work/row${#rows[@]}.png")
  done
  convert "${rows[@]}" -background white -gravity center -append "$out/$target"
}
demo=$work/riser-demo/mission
noise=$work/riser-demo/noise.yaml
for z in 1.5 2 3; do
  run "z$z" "$demo" "$noise" "detector: {z: $z}"
  fan "z$z" && map "z$z"
done
side_by_side guide_param_z.png 3 "z = 1.5|z1.5_fan.png" "z = 2 (default)|z2_fan.png" \
  "z = 3|z3_fan.png" "z = 1.5|z1.5_map.png" "z = 2|z2_map.png" "z = 3|z3_map.png"
run smoothing1 "$demo" "$work/riser-demo/noise-smoothing1.yaml" "detector: {smoothing: 1}"
fan smoothing1 && map smoothing1
side_by_side guide_param_smoothing.png 2 "smoothing 1 (none)|smoothing1_fan.png" \
  "smoothing 3 (default)|z2_fan.png" "smoothing 1|smoothing1_map.png" "smoothing 3|z2_map.png"
for views in 1 15; do
  run "views$views" "$demo" "$noise" "min_views: $views"
  map "views$views"
done
side_by_side guide_param_min_views.png 3 "min views 1|views1_map.png" \
  "5 (default)|z2_map.png" "15|views15_map.png"
for voxel in 0.05 0.1; do
  run "voxel$voxel" "$demo" "$noise" "voxel_size_m: $voxel"
  map "voxel$voxel"
done
side_by_side guide_param_voxel.png 3 "voxel 2 cm (default)|z2_map.png" \
  "5 cm|voxel0.05_map.png" "10 cm|voxel0.1_map.png"
for stride in 2 4; do
  run "stride$stride" "$demo" "$noise" "frames: {stride: $stride}"
  map "stride$stride"
done
side_by_side guide_param_stride.png 3 "stride 1 (98 frames)|z2_map.png" \
  "stride 2 (49 frames)|stride2_map.png" "stride 4 (25 frames)|stride4_map.png"
cp "$work/z2.png" "$out/guide_workbench_frame60.png"

# ---- Part 3: troubleshooting. The orbit as simulated, with its frames 10 s late on the
# navigation, and with headings read in the wrong convention (ENU instead of compass).
orbit=$work/orbit
rm -rf "$orbit/late" "$orbit/enu"
cp -r "$orbit/mission" "$orbit/late"
cp -r "$orbit/mission" "$orbit/enu"
awk -F, -v OFS=, 'NR == 1 { print; next } { $1 += 10; print }' "$orbit/mission/frames.csv" |
  head -n -10 >"$orbit/late/frames.csv"
awk -F, -v OFS=, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "yaw_deg") c = i; print; next }
  { $c = 90 - $c; print }' "$orbit/mission/nav.csv" >"$orbit/enu/nav.csv"
for case in mission late enu; do
  run "orbit_$case" "$orbit/$case" "$orbit/noise.yaml" "# defaults"
  map "orbit_$case"
done
side_by_side guide_trouble_navigation.png 3 "navigation right|orbit_mission_map.png" \
  "frames 10 s late|orbit_late_map.png" "heading as ENU|orbit_enu_map.png"
echo "pictures written to $out"
