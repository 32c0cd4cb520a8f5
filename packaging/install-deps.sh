#!/usr/bin/env bash
# Installs every Debian 12 package SonarCarve needs to build, test and run.
# Idempotent: packages already present are left alone. Works as root or through sudo.
set -euo pipefail

packages=(
  # toolchain
  build-essential cmake ninja-build pkg-config git clang-format
  # core libraries
  libeigen3-dev liboctomap-dev libembree-dev libyaml-cpp-dev libcli11-dev nlohmann-json3-dev
  libopencv-core-dev libopencv-imgproc-dev libpng-dev zlib1g-dev
  # coordinate reference systems (core/geo/): PROJ and its database of CRSs
  libproj-dev proj-data
  # the seabed's elevation grid as GeoTIFF (core/io/raster/): GDAL
  libgdal-dev
  # the tests read and write pictures with OpenCV too
  libopencv-imgcodecs-dev
  # ROS 2 bags: SQLite3 storage, lz4 and zstd chunks of MCAP files
  libsqlite3-dev liblz4-dev libzstd-dev
  libvtk9-dev
  # GUI
  qt6-base-dev libqt6opengl6-dev libgl-dev libgl1-mesa-dri
  # tests and benchmarks
  libgtest-dev libgmock-dev libbenchmark-dev xvfb xauth octomap-tools assimp-utils
  # PROJ's cs2cs: the georeferenced export is checked against it (tests/e2e/geodetic_nav_test.cpp)
  proj-bin
  # GDAL's gdalinfo and gdalsrsinfo: the GeoTIFF and LAS exports' CRS, extent and heights are
  # checked with them (tests/e2e/geodetic_nav_test.cpp, seabed_grid_test.cpp)
  gdal-bin
  # a headless browser: the survey report (report.html) opens offline in it (tests/e2e/report_page_test.cpp)
  chromium
  # the Debian package (packaging/README.md): CPack's DEB generator, man pages, the package test
  dpkg-dev help2man lintian desktop-file-utils appstream man-db
)
# Fuzzing (the fuzz preset, docs/fuzzing.md) also needs clang-14 and libclang-rt-14-dev; it is
# not part of the test suite, so they are not installed here.

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi

if [ "$(id -u)" -eq 0 ]; then
  SUDO=()
elif command -v sudo >/dev/null 2>&1; then
  SUDO=(sudo)
else
  echo "install-deps: need root or sudo to install: ${missing[*]}" >&2
  exit 1
fi

echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${SUDO[@]}" apt-get update -q
"${SUDO[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
