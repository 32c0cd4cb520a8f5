// Point clouds as PLY with named per-point properties (VTK 9.1's PLY writer keeps only x, y, z,
// so SonarCarve writes and reads its point clouds itself). Writing: binary little-endian,
// float properties then uint ones, atomically. Reading: ascii or binary (either byte order),
// any numeric vertex property, converted to float; the vertex element must come first.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace sonarcarve {

struct PointCloud {
  std::vector<Eigen::Vector3f> positions;
  std::map<std::string, std::vector<float>> properties;  ///< one value per point
  /// Header comments after SonarCarve's first one (written) or all of them (read).
  std::vector<std::string> comments;
};

using Triangles = std::vector<std::array<std::uint32_t, 3>>;

/// `uint_properties` are written as uint32; `triangles`, when given, as a face element (a
/// mesh). Throws Error if a property's size differs.
void writePointCloudPly(
    const std::filesystem::path& path, const PointCloud& cloud,
    const std::map<std::string, std::vector<std::uint32_t>>& uint_properties = {},
    const Triangles& triangles = {});
/// Throws Error naming the file and the place on a missing, truncated or malformed file, or a
/// vertex that is not finite. `origin_ned_m` is subtracted from every position in double, before
/// it becomes a float (world coordinates far from zero read into a mission's local frame).
PointCloud readPointCloudPly(const std::filesystem::path& path,
                             const Eigen::Vector3d& origin_ned_m = Eigen::Vector3d::Zero());

/// The origin a PLY file's header carries (originComment, sonar/mission_origin.h), zero when it
/// carries none. Throws
/// Error naming the file on an origin comment that is not three finite numbers.
Eigen::Vector3d plyOrigin(const std::filesystem::path& path);

/// The CRS a PLY file's header carries (crsComment, geo/crs.h: the grid its world frame is),
/// empty when it carries none. Throws Error naming the file on a crs comment without a CRS.
std::string plyCrs(const std::filesystem::path& path);

struct PlyMesh {
  PointCloud vertices;
  Triangles triangles;
};
/// A mesh: the vertices as readPointCloudPly reads them, then the face element, polygons split
/// into triangles. Throws Error naming the face whose vertex index is out of range.
PlyMesh readPlyMesh(const std::filesystem::path& path,
                    const Eigen::Vector3d& origin_ned_m = Eigen::Vector3d::Zero());

}  // namespace sonarcarve
