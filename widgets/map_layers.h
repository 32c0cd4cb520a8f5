// The 3D view's layers as VTK data: the points of map blocks (every n-th, inside a clip
// region) with their colour values, and a mesh. Plain functions on data, no widget and no
// rendering: they may run on a worker thread, the GUI thread then only hands the result to
// a mapper (MapView does; docs/benchmarks.md measures why).
#pragma once

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "map_view_block.h"
#include "mesh/surface_mesher.h"
#include "occlusion/surface_points.h"

namespace sonarcarve::widgets {

/// What the points of the 3D view are coloured by.
enum class ColourBy { Intensity, Depth, Error };

/// A layer's colouring: a value per drawn point and the colour scale's ends.
struct LayerColours {
  vtkSmartPointer<vtkFloatArray> scalars;
  ColourBy by = ColourBy::Intensity;
  double low = 0.0;
  double high = 1.0;
};

/// A layer ready to draw: its polydata with the colour values as its scalars.
struct PreparedLayer {
  vtkSmartPointer<vtkPolyData> poly;
  std::size_t stride = 1;  ///< every stride-th point (inside the region) is drawn
  LayerColours colours;
};

/// A mesh's vertices (with their intensities and errors in a MapViewBlock) and triangles.
struct MeshData {
  MapViewBlock vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<Eigen::Vector3f> normals;  ///< one per vertex, or empty
};

/// A mesh with its vertices' intensities (0 where it has none) and errors (may be empty).
MeshData meshData(const Mesh& mesh, std::vector<float> vertex_errors_m = {});
/// Surface points as a block: positions, intensities and errors (may be empty).
MapViewBlock surfaceBlock(const SurfacePoints& surface, std::vector<float> errors_m = {});

/// The name of the point array of the voxels each drawn point stands for.
inline constexpr const char* kVoxelsArray = "voxels";

/// Cells that draw each of `count` points, or the points in order as one polyline.
vtkSmartPointer<vtkCellArray> pointCells(vtkIdType count, bool as_line);

/// How many voxels the points of `blocks` inside `region` (all without one) stand for: their
/// number at full detail.
std::size_t voxelsInside(const std::vector<const MapViewBlock*>& blocks,
                         const Eigen::AlignedBox3d* region);

/// The stride that draws at most `max_points` of `count` voxels.
std::size_t strideFor(std::size_t count, std::size_t max_points);

/// The values of the points of `blocks` inside `region` drawn at `stride`, by `by` (intensity:
/// the scale ends at the 98th percentile; depth: the range; error: 0 to 10 cm).
LayerColours layerColours(const std::vector<const MapViewBlock*>& blocks,
                          const Eigen::AlignedBox3d* region, std::size_t stride, ColourBy by);

/// The points of `blocks` inside `region` drawn at `stride` as vertices, coloured by `by`:
/// every stride-th voxel; a point standing for several voxels (a coarser level of detail) is
/// drawn when one of its voxels would be, so one standing for `stride` voxels or more always.
/// At most ceil(voxelsInside / stride) points. When some stand for several voxels, the
/// polydata's point array kVoxelsArray says how many each does.
PreparedLayer preparePoints(const std::vector<const MapViewBlock*>& blocks,
                            const Eigen::AlignedBox3d* region, std::size_t stride, ColourBy by);

/// The mesh's triangles whose centre lies inside `region` (all without one), its normals, and
/// every vertex coloured by `by`.
PreparedLayer prepareMesh(const MeshData& mesh, const Eigen::AlignedBox3d* region, ColourBy by);

}  // namespace sonarcarve::widgets
