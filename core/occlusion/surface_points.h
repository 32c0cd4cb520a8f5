// SurfacePoints: the reconstruction's output, the front surface of the structure as points in
// the world frame (NED, metres), each with its carved intensity and the number of views in
// which it was the first return.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace sonarcarve {

struct SurfacePoint {
  Eigen::Vector3f position_m;
  float intensity = 0.0f;
  std::uint32_t views = 0;
};

using SurfacePoints = std::vector<SurfacePoint>;

/// The points' positions alone (for evaluation and distance colouring).
std::vector<Eigen::Vector3f> positionsOf(const SurfacePoints& points);

/// Binary PLY with vertex properties x, y, z (float), intensity (float), views (uint), and a
/// header comment with the mission origin when it is not zero (io/mesh/point_cloud_ply.h).
/// Atomic: a failure keeps the previous file.
/// A mission with a CRS (`crs`, not empty) has it in a comment too (geo/crs.h).
void writeSurfacePointsPly(const SurfacePoints& points, const std::filesystem::path& path,
                           const Eigen::Vector3d& origin_ned_m = Eigen::Vector3d::Zero(),
                           const std::string& crs = "");
/// Reads x, y, z (and intensity, views when present) of a PLY point cloud.
SurfacePoints readSurfacePointsPly(const std::filesystem::path& path);

}  // namespace sonarcarve
