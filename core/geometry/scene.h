// Scene: a triangle mesh in the world frame (NED, metres) with a smooth-shading normal per
// vertex and an acoustic reflectivity per triangle, plus where an inspection should look.
// The mesh type that the simulator, surface extraction and evaluation share. Plain data, no
// VTK types: mesh files are read and written by geometry/scene_io, VTK conversions live in
// geometry/internal/vtk_mesh. Limits: float coordinates, so keep scenes within a few km of the
// origin.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace sonarcarve {

struct InspectionTarget {
  Eigen::Vector3d axis_point_m = Eigen::Vector3d::Zero();  ///< a point on the structure's axis
  double top_down_m = 0.0;                                 ///< shallowest depth worth inspecting
  double bottom_down_m = 0.0;                              ///< deepest depth worth inspecting
  double seabed_down_m = 0.0;  ///< depth of the seabed under the target (0: none)
};

struct Scene {
  std::string name;
  std::vector<Eigen::Vector3f> vertices;  ///< world NED, metres
  std::vector<Eigen::Vector3f> normals;   ///< unit, per vertex, for smooth shading
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<float> reflectivity;  ///< per triangle, in [0, 1]
  InspectionTarget target;

  /// Appends another scene's triangles (its target is ignored).
  void append(const Scene& other);
  Eigen::Vector3d boundsMin() const;
  Eigen::Vector3d boundsMax() const;
  /// Total area of the triangles, square metres.
  double area() const;
  /// A target derived from the bounding box: axis through its centre, full depth span.
  InspectionTarget boundingBoxTarget() const;
};

}  // namespace sonarcarve
