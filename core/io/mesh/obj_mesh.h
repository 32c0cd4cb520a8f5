// Wavefront OBJ meshes, read by SonarCarve itself: VTK 9.1's reader takes "nan" for a number
// without a word and lets a face name a vertex that does not exist.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <vector>

#include "io/mesh/point_cloud_ply.h"

namespace sonarcarve {

struct ObjMesh {
  std::vector<Eigen::Vector3f> vertices;
  Triangles triangles;  ///< polygons split into fans
};

/// Reads the `v` and `f` lines (indices from 1, or negative from the end; texture and normal
/// indices after a slash are ignored); other lines are skipped. Throws Error naming the file,
/// the line and what was expected for a vertex that is not three finite numbers or a face
/// whose index names no vertex.
/// `origin_ned_m` is subtracted from every vertex, in double, before it becomes a float (a mesh
/// in world coordinates far from zero read into a mission's local frame).
ObjMesh readObjMesh(const std::filesystem::path& path,
                    const Eigen::Vector3d& origin_ned_m = Eigen::Vector3d::Zero());

}  // namespace sonarcarve
