// The occupancy mesher's contour (mesh/surface_mesher.h), tile by tile: the points' voxels
// are marked 1 on a grid aligned with the map's (sample i at the centre of voxel i), Gaussian
// smoothed (vtkImageGaussianSmooth) and contoured with flying edges, one tile of
// `tile_voxels` cells a side at a time. Each tile is smoothed with a border as wide as the
// kernel reaches, so its samples are those a whole-box grid would hold (to float rounding),
// and the vertices on a plane two tiles share are merged by the grid edge they lie on: the
// pieces join into one seamless surface. Memory is that of one tile plus the
// surface, whatever the extent of the points (the whole box of a long survey's seabed would
// not fit; docs/benchmarks.md).
#pragma once

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "occlusion/surface_points.h"

namespace sonarcarve {

struct OccupancyContourParams {
  double voxel_size_m = 0.02;
  double sigma_voxels = 0.7;  ///< Gaussian smoothing of the occupancy
  double iso = 0.25;          ///< contour level of the smoothed occupancy
  int tile_voxels = 64;       ///< cells per tile side
};

/// The contour of the points' smoothed occupancy, world frame (metres); triangles only,
/// coincident points merged. Empty when there are no points.
vtkSmartPointer<vtkPolyData> occupancyContour(const SurfacePoints& points,
                                              const OccupancyContourParams& params);

}  // namespace sonarcarve
