#!/usr/bin/env bash
# test-package.sh SOURCE_DIR BUILD_DIR CPACK: the package test (CTest label `package`,
# packaging/README.md). Builds the Debian package with CPack, checks its contents, validates
# the desktop entry, the metainfo and the man pages, runs lintian (errors and warnings fail),
# installs the package with apt, moves the build tree out of the way, and runs the installed
# programs from a clean environment: --version, --help, a short simulate -> noise-model ->
# reconstruct of the riser demo, and the workbench on the installed example mission under
# Xvfb. The build tree is put back and the package removed however the test ends.
#
# It installs a package system-wide, so it needs root (CI has it) and runs alone (RUN_SERIAL):
# without root it is skipped (exit 77).
set -euo pipefail
src=$(cd "$1" && pwd)
build=$(cd "$2" && pwd)
cpack=$3
start=$SECONDS
step() { printf '\n== %s (%ds)\n' "$*" $((SECONDS - start)); }
fail() {
  echo "FAIL: $*" >&2
  exit 1
}

if [ "$(id -u)" -ne 0 ]; then
  echo "SKIP: the package test installs a .deb system-wide and needs root"
  exit 77
fi
for tool in dpkg-deb dpkg-parsechangelog lintian desktop-file-validate appstreamcli apt-get \
  xvfb-run flock; do
  command -v "$tool" >/dev/null || fail "$tool is missing: run packaging/install-deps.sh"
done

work=$(mktemp -d /tmp/sonarcarve-package-test.XXXXXX)
moved="$build.moved-by-package-test.$$"
installed=0
watchdog=
cleanup() {
  local status=$?
  cd /
  [ -z "$watchdog" ] || kill "$watchdog" 2>/dev/null || true
  if [ -d "$moved" ] && [ ! -e "$build" ]; then
    mv "$moved" "$build" && echo "build tree put back: $build"
  fi
  if [ "$installed" = 1 ]; then
    DEBIAN_FRONTEND=noninteractive apt-get remove --purge -y -q -o DPkg::Lock::Timeout=300 \
      sonarcarve >"$work/remove.log" 2>&1 || { cat "$work/remove.log"; status=1; }
    [ ! -e /usr/bin/sonarcarve-cli ] || { echo "FAIL: still installed after removal"; status=1; }
    echo "package removed"
  fi
  rm -rf "$work"
  exit "$status"
}
trap cleanup EXIT
trap 'exit 143' TERM INT HUP

step "Building the package (cpack -G DEB)"
rm -rf "$build/package"
"$cpack" -G DEB --config "$build/CPackConfig.cmake" -B "$build/package" >"$work/cpack.log" 2>&1 ||
  { cat "$work/cpack.log"; fail "cpack"; }
debs=("$build"/package/sonarcarve_*.deb)
[ ${#debs[@]} -eq 1 ] && [ -f "${debs[0]}" ] || fail "expected one .deb in $build/package"
deb=${debs[0]}
version=$(dpkg-deb -f "$deb" Version)
echo "$deb: $(du -k "$deb" | cut -f1) KiB, version $version"
dpkg-deb -f "$deb" Depends
[ "$version" = "$(dpkg-parsechangelog -l "$src/packaging/changelog" -S Version)" ] ||
  fail "packaging/changelog's last entry is not $version"
grep -q "<release version=\"$version\"" "$src"/packaging/*.metainfo.xml ||
  fail "the metainfo has no release $version"

step "Contents"
dpkg-deb -c "$deb" | awk '{print $6}' | sed 's|^\./|/|' >"$work/contents"
app_id=io.github.sonarcarve.SonarCarve
multiarch=$(dpkg-architecture -qDEB_HOST_MULTIARCH)
expected=(
  /usr/bin/sonarcarve /usr/bin/sonarcarve-cli
  "/usr/lib/$multiarch/sonarcarve/libsonarcarve_core.so"
  /usr/share/applications/$app_id.desktop /usr/share/metainfo/$app_id.metainfo.xml
  /usr/share/icons/hicolor/scalable/apps/sonarcarve.svg
  /usr/share/man/man1/sonarcarve.1.gz /usr/share/man/man1/sonarcarve-cli.1.gz
  /usr/share/doc/sonarcarve/copyright /usr/share/doc/sonarcarve/changelog.gz
  /usr/share/doc/sonarcarve/user-guide/README.md /usr/share/doc/sonarcarve/images/
  /usr/share/sonarcarve/example_mission/mission.yaml /usr/share/lintian/overrides/sonarcarve
)
for size in 16 32 48 64 128 256; do
  expected+=("/usr/share/icons/hicolor/${size}x$size/apps/sonarcarve.png")
done
for path in "${expected[@]}"; do
  grep -qxF "$path" "$work/contents" || fail "$path is not in the package"
done
if grep -v '^/usr/' "$work/contents" | grep -vx '/'; then fail "files outside /usr"; fi
echo "all ${#expected[@]} expected paths present; $(grep -vc '/$' "$work/contents") files"
dpkg-deb -f "$deb" Depends | grep -q libqt6widgets6 || fail "Depends lacks the Qt libraries"

step "Desktop entry, metainfo, icons, man pages"
root="$work/root"
dpkg-deb -x "$deb" "$root"
desktop-file-validate "$root/usr/share/applications/$app_id.desktop"
appstreamcli validate --no-net --strict "$root/usr/share/metainfo/$app_id.metainfo.xml"
for size in 16 32 48 64 128 256; do
  png="$root/usr/share/icons/hicolor/${size}x$size/apps/sonarcarve.png"
  # PNG: width and height are big-endian words at bytes 16 and 20.
  read -r w h < <(od -An -tu1 -j16 -N8 "$png" |
    awk '{print $1*16777216+$2*65536+$3*256+$4, $5*16777216+$6*65536+$7*256+$8}')
  [ "$w $h" = "$size $size" ] || fail "$png is $w x $h"
done
for page in "$root"/usr/share/man/man1/*.1.gz; do
  warnings=$(LC_ALL=C.UTF-8 MANWIDTH=80 man --warnings -E UTF-8 -l "$page" 2>&1 >/dev/null)
  [ -z "$warnings" ] || fail "man page $page: $warnings"
  grep -q '^\.SH OPTIONS' <(zcat "$page") || fail "$page has no OPTIONS"
done
# Nothing installed may point into the source or build tree (man pages: uncompressed).
if grep -rlaF -e "$src" -e "$build" "$root" ||
  zcat "$root"/usr/share/man/man1/*.gz | grep -aF -e "$src" -e "$build"; then
  fail "installed files name the source or build tree"
fi
echo "valid; no installed file names $src or $build"

step "lintian"
# Root is not recommended to unpack foreign packages; this one was just built here.
lintian_status=0
lintian --fail-on error,warning --display-info --show-overrides "$deb" >"$work/lintian.txt" 2>&1 ||
  lintian_status=$?
grep -v '^running with root privileges' "$work/lintian.txt" || true
[ "$lintian_status" -eq 0 ] || fail "lintian reports errors or warnings (exit $lintian_status)"
echo "lintian: $(grep -c '^[EW]:' "$work/lintian.txt" || true) errors and warnings," \
  "$(grep -c '^I:' "$work/lintian.txt" || true) info, $(grep -c '^O:' "$work/lintian.txt" || true)" \
  "overridden"

# From here the package is on the system: one package test at a time on this machine.
exec 9>/var/lock/sonarcarve-package-test.lock
flock -w 600 9 || fail "another package test holds /var/lock/sonarcarve-package-test.lock"

step "apt-get install"
if dpkg-query -W -f='${Status}' sonarcarve 2>/dev/null | grep -q "install ok installed"; then
  echo "note: a sonarcarve package was installed before the test; it is replaced and removed"
fi
installed=1
DEBIAN_FRONTEND=noninteractive apt-get install -y -q -o DPkg::Lock::Timeout=300 "$deb" \
  >"$work/install.log" 2>&1 || { cat "$work/install.log"; fail "apt-get install"; }
grep -E '^(Setting up|The following NEW)' "$work/install.log" || true
core=/usr/lib/$multiarch/sonarcarve/libsonarcarve_core.so
for program in sonarcarve sonarcarve-cli; do
  ldd "/usr/bin/$program" >"$work/ldd" || fail "ldd $program"
  if grep 'not found' "$work/ldd"; then fail "$program misses libraries"; fi
  loaded=$(sed -n 's/.*libsonarcarve_core.so => \([^ ]*\) .*/\1/p' "$work/ldd")
  [ "$(readlink -f "$loaded")" = "$core" ] || fail "$program loads the core from '$loaded'"
done
echo "both programs load $core and find every library"

step "Build tree moved out of the way: $build -> $moved"
cd "$work"
mv "$build" "$moved"
# The build tree must come back even if something hangs: each program gets 100 s, and a
# watchdog ends the test (the EXIT trap puts the tree back) 760 s after it started, before
# CTest's time-out (900 s) would kill it without running the trap.
main=$$
(
  trap 'kill $sleeper 2>/dev/null; exit 0' TERM
  sleep $((SECONDS < 750 ? 760 - SECONDS : 10)) &
  sleeper=$!
  wait $sleeper && kill -TERM $main
) >/dev/null 2>&1 &
watchdog=$!
# The installed programs run with a clean environment, from an empty folder.
run() {
  timeout 100 env -i HOME="$work" PATH=/usr/bin:/bin LANG=C.UTF-8 "$@"
}
out=$(run sonarcarve-cli --version)
echo "$out"
[ "$out" = "sonarcarve-cli $version" ] || fail "sonarcarve-cli --version said '$out'"
out=$(run sonarcarve --version 2>/dev/null)
echo "$out"
[ "$out" = "SonarCarve $version" ] || fail "sonarcarve --version said '$out'"
# Help texts are captured whole: `grep -q` on a pipe stops reading at the first match, and the
# program writing the rest then dies of SIGPIPE, which pipefail reports as a failure.
out=$(run sonarcarve --help 2>/dev/null)
grep -q -- '--noise-model' <<<"$out" || fail "sonarcarve --help"
out=$(run sonarcarve-cli reconstruct --help)
grep -q -- '--noise-model' <<<"$out" || fail "reconstruct --help"

step "Installed demo: simulate -> noise-model -> reconstruct"
frames=40
run sonarcarve-cli simulate --scene riser --max-frames $frames --out demo/mission --force
run sonarcarve-cli simulate --scene riser --empty-water --seed 99 --max-frames $frames \
  --out demo/empty-water --force
run sonarcarve-cli noise-model demo/empty-water --out demo/noise.yaml
run sonarcarve-cli reconstruct demo/mission --noise-model demo/noise.yaml --out demo/reconstruction
for file in surface_points.ply mesh.ply mesh.stl map.bt report.json; do
  [ -s "demo/reconstruction/$file" ] || fail "reconstruct wrote no $file"
done
fscore=$(grep -o '"fscore": *[0-9.e+-]*' demo/reconstruction/report.json | head -n 1 |
  sed 's/.*: *//')
echo "F-score of the $frames-frame reconstruction: ${fscore:-none}"
awk -v f="${fscore:-0}" 'BEGIN { exit !(f > 0.3 && f <= 1) }' ||
  fail "report.json has no plausible F-score"

step "Installed workbench under Xvfb on the installed example mission"
run QT_QPA_PLATFORM=xcb xvfb-run -a -s '-screen 0 1280x800x24' sonarcarve \
  /usr/share/sonarcarve/example_mission --quit-when-done --screenshot "$work/workbench.png" \
  >"$work/gui.log" 2>&1 || { cat "$work/gui.log"; fail "the installed workbench"; }
[ -s "$work/workbench.png" ] || fail "no screenshot from the installed workbench"
echo "the workbench ran the example mission and saved its window"

step "Done: putting the build tree back and removing the package"
