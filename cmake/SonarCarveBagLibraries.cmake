# The libraries of the ROS 2 bag readers (Debian 12: libsqlite3-dev, liblz4-dev, libzstd-dev),
# as SONARCARVE_BAG_LIBS: used by sonarcarve_core and by the fuzz targets.
find_package(SQLite3 REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(SONARCARVE_LZ4 REQUIRED IMPORTED_TARGET liblz4)
pkg_check_modules(SONARCARVE_ZSTD REQUIRED IMPORTED_TARGET libzstd)
set(SONARCARVE_BAG_LIBS SQLite::SQLite3 PkgConfig::SONARCARVE_LZ4 PkgConfig::SONARCARVE_ZSTD)
