// LAS 1.4 point clouds (ASPRS LAS Specification 1.4 R15), written by SonarCarve itself: Debian
// 12 packages no LAS library. What is written, and only that:
//   header   375 bytes, version 1.4, point data record format 6 (30 bytes a point), global
//            encoding bit 4 (the CRS is WKT, which format 6 requires), creation day and year 0
//            (unknown: two exports of one map are the same bytes), no waveforms, no EVLR
//   VLR      when a CRS is given: user "LASF_Projection", record 2112, the OGC WKT of the CRS
//            with its terminating NUL
//   points   X, Y, Z int32 = round((coordinate - offset) / scale); intensity u16; single
//            returns (return 1 of 1); classification as given; views in user data (at most
//            255); scan angle, point source and GPS time 0
// Scale and offset: the scale is 0.1 mm when the cloud's extent fits int32 at that step (214 km
// about the offset), otherwise 1 mm (2147 km), otherwise refused; the offset is the centre of
// the cloud's box rounded to a whole metre. A coordinate is thus kept to half the scale (0.05 mm
// at eastings and northings of millions of metres). The header's extent is that of the stored
// (rounded) coordinates.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace sonarcarve {

/// ASPRS standard classes (LAS 1.4, table 17) that SonarCarve assigns.
enum class LasClass : std::uint8_t { NeverClassified = 0, Unclassified = 1, Ground = 2 };

struct LasPoint {
  Eigen::Vector3d xyz;  ///< x east(ing), y north(ing), z up, metres
  std::uint16_t intensity = 0;
  LasClass classification = LasClass::NeverClassified;
  std::uint8_t user_data = 0;
};

struct LasCloud {
  std::vector<LasPoint> points;
  std::string crs_wkt;  ///< OGC WKT of the coordinates' CRS; empty: no CRS record
  std::string generating_software = "SonarCarve";
};

/// The file's bytes. Throws Error(`target`, ...) for a coordinate that is not finite or an
/// extent beyond what int32 holds at 1 mm.
std::string lasBytes(const LasCloud& cloud, const std::string& target);

/// lasBytes written through writeFileAtomically: a failure keeps the previous file.
void writeLasFile(const std::filesystem::path& path, const LasCloud& cloud);

/// The scale lasBytes picks for a cloud whose coordinates lie within `half_extent_m` of the
/// offset on every axis (0.0001 or 0.001), or 0 when none fits.
double lasScaleFor(double half_extent_m);

}  // namespace sonarcarve
