// A LAS 1.4 reader for the tests, written from the ASPRS LAS 1.4 R15 tables (public header
// block, table 3; VLR header, table 14; point data record format 6, table 11), apart from
// the writer it checks (core/io/mesh/las_file.cpp): every field is read at the byte offset the
// specification gives, not through the writer's layout. No Debian 12 package reads LAS (pdal,
// laspy and liblas are not packaged; CloudCompare is built without LAS), so this is the
// reader the tests have; the CRS record's WKT is checked by GDAL's gdalsrsinfo.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace sonarcarve::test {

struct LasReadBack {
  std::uint8_t version_major = 0, version_minor = 0;
  std::uint16_t global_encoding = 0, header_size = 0;
  std::uint8_t point_format = 0;
  std::uint16_t point_size = 0;
  std::uint32_t legacy_count = 0;
  std::uint64_t count = 0;
  Eigen::Vector3d scale, offset, min, max;
  std::string wkt;  ///< LASF_Projection record 2112, without its NUL; empty when absent
  std::vector<Eigen::Vector3d> points;
  std::vector<std::uint16_t> intensity;
  std::vector<std::uint8_t> classification, user_data, returns;
};

/// Reads `path`; fails the calling test (ADD_FAILURE) and returns what it read on a file
/// shorter than its header or its counts say.
LasReadBack readLasBack(const std::filesystem::path& path);

}  // namespace sonarcarve::test
