// Surface meshes from the reconstruction's surface points, with VTK's filters:
//   occupancy  (default) the points' voxels, Gaussian smoothed (vtkImageGaussianSmooth,
//              sigma 0.7 voxel) and contoured at 0.25 with flying edges: a thin closed skin
//              around the sheet of points, within about 0.6 voxel of it. Fast (0.5 s).
//              Tile by tile (mesh/internal/occupancy_contour.h): memory follows the
//              surface, not its bounding box.
//   implicit   Hoppe et al.'s signed distance to the points' tangent planes
//              (vtkSurfaceReconstructionFilter) contoured at zero, so vertices lie on the
//              points' surface; the contour also closes over places no point supports, so
//              triangles farther than `max_distance_voxels` from every point are removed.
//              Samples the whole bounding box: minutes for the riser (docs/meshes.md).
// then: fragments under `min_fragment_triangles` removed (vtkPolyDataConnectivityFilter),
// windowed-sinc smoothing, optional decimation (vtkQuadricDecimation), normals. Each vertex
// takes the intensity and view count of its nearest surface point. World frame, metres.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "common/enum_names.h"
#include "occlusion/surface_points.h"

namespace sonarcarve {

enum class MeshMethod { Occupancy, Implicit };
inline constexpr std::array<EnumName<MeshMethod>, 2> kMeshMethodNames{{
    {MeshMethod::Occupancy, "occupancy"},
    {MeshMethod::Implicit, "implicit"},
}};
constexpr const auto& enumNamesOf(MeshMethod) {
  return kMeshMethodNames;
}

struct MeshParams {
  MeshMethod method = MeshMethod::Occupancy;
  double voxel_size_m = 0.02;  ///< sampling of the implicit function
  double max_distance_voxels = 2.0;
  std::size_t min_fragment_triangles = 200;
  int smoothing_iterations = 15;  ///< windowed sinc; 0 = none
  double smoothing_passband = 0.1;
  double decimate = 0.0;                ///< fraction of triangles removed, 0..0.95
  double occupancy_sigma_voxels = 0.7;  ///< occupancy: Gaussian smoothing of the voxels
  double occupancy_iso = 0.25;          ///< occupancy: contour level of the smoothed field
  void validate() const;
};

struct Mesh {
  std::vector<Eigen::Vector3f> vertices;
  std::vector<Eigen::Vector3f> normals;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<float> intensity;      ///< per vertex
  std::vector<std::uint32_t> views;  ///< per vertex
};

/// Throws Error if there are too few points (fewer than 10).
Mesh meshSurface(const SurfacePoints& points, const MeshParams& params);

}  // namespace sonarcarve
