#include "support/las_read_back.h"

#include <gtest/gtest.h>

#include <cstring>

#include "support/test_support.h"

namespace sonarcarve::test {
namespace {

template <typename T>
T at(const std::string& bytes, std::size_t offset) {
  T value{};
  if (offset + sizeof(T) > bytes.size()) {
    ADD_FAILURE() << "LAS read back: field at byte " << offset << " beyond the file's "
                  << bytes.size() << " bytes";
    return value;
  }
  std::memcpy(&value, bytes.data() + offset, sizeof(T));
  return value;
}

Eigen::Vector3d threeDoubles(const std::string& bytes, std::size_t offset, std::size_t stride) {
  return {at<double>(bytes, offset), at<double>(bytes, offset + stride),
          at<double>(bytes, offset + 2 * stride)};
}

}  // namespace

LasReadBack readLasBack(const std::filesystem::path& path) {
  const std::string bytes = readText(path);
  LasReadBack las;
  EXPECT_EQ(bytes.substr(0, 4), "LASF") << path;
  las.global_encoding = at<std::uint16_t>(bytes, 6);
  las.version_major = at<std::uint8_t>(bytes, 24);
  las.version_minor = at<std::uint8_t>(bytes, 25);
  las.header_size = at<std::uint16_t>(bytes, 94);
  const auto point_offset = at<std::uint32_t>(bytes, 96);
  const auto vlrs = at<std::uint32_t>(bytes, 100);
  las.point_format = at<std::uint8_t>(bytes, 104);
  las.point_size = at<std::uint16_t>(bytes, 105);
  las.legacy_count = at<std::uint32_t>(bytes, 107);
  las.scale = threeDoubles(bytes, 131, 8);
  las.offset = threeDoubles(bytes, 155, 8);
  las.max = threeDoubles(bytes, 179, 16);
  las.min = threeDoubles(bytes, 187, 16);
  las.count = at<std::uint64_t>(bytes, 247);
  std::size_t vlr = las.header_size;
  for (std::uint32_t i = 0; i < vlrs && vlr + 54 <= bytes.size(); ++i) {
    const std::string user(bytes.data() + vlr + 2, strnlen(bytes.data() + vlr + 2, 16));
    const auto record = at<std::uint16_t>(bytes, vlr + 18);
    const auto length = at<std::uint16_t>(bytes, vlr + 20);
    if (user == "LASF_Projection" && record == 2112 && vlr + 54 + length <= bytes.size()) {
      las.wkt.assign(bytes.data() + vlr + 54, strnlen(bytes.data() + vlr + 54, length));
    }
    vlr += 54 + length;
  }
  EXPECT_EQ(vlr, point_offset) << "the VLRs end where the points start";
  for (std::uint64_t i = 0; i < las.count; ++i) {
    const std::size_t p = point_offset + i * las.point_size;
    if (p + las.point_size > bytes.size()) {
      ADD_FAILURE() << path << ": point " << i << " beyond the file";
      break;
    }
    Eigen::Vector3d xyz;
    for (int a = 0; a < 3; ++a) {
      xyz[a] = las.offset[a] + las.scale[a] * at<std::int32_t>(bytes, p + 4 * a);
    }
    las.points.push_back(xyz);
    las.intensity.push_back(at<std::uint16_t>(bytes, p + 12));
    las.returns.push_back(at<std::uint8_t>(bytes, p + 14));
    las.classification.push_back(at<std::uint8_t>(bytes, p + 16));
    las.user_data.push_back(at<std::uint8_t>(bytes, p + 17));
  }
  EXPECT_EQ(point_offset + las.count * las.point_size, bytes.size()) << "no bytes after the points";
  return las;
}

}  // namespace sonarcarve::test
