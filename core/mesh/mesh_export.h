// Deliverables: meshes and point clouds as files other tools open (docs/formats.md).
//   ply        binary little-endian PLY: vertices (x, y, z, nx, ny, nz, intensity, views)
//              and triangles; `ply-ascii` the same in ASCII
//   stl        binary STL (triangles only)
//   obj        Wavefront OBJ with vertex normals
//   las        LAS 1.4 point cloud (points only, io/mesh/las_file.h): x east(ing), y
//              north(ing), z up; in the target CRS, else in the mission's CRS (world
//              coordinates), with the CRS's WKT; without a CRS local (or world with
//              add_mission_origin) and no CRS record
//   geotiff    the seabed's elevation grid from the points (mesh/seabed_grid.h), Float32
//              heights up in metres, in the same coordinates and CRS as las (GDAL)
// Units are metres. Coordinates inside are local to the mission origin (sonar/mission_origin.h);
// `add_mission_origin` adds it back (world coordinates, written in double: PLY `property
// double`, OBJ with 6 decimals; STL, float32 only, is refused). Frames: `ned` writes north,
// east, down as inside; `zup` writes x = east, y = north, z = up (= -down), the right-handed
// Z-up frame CAD tools expect; an optional origin (NED) is subtracted first so that coordinates
// stay small. A PLY whose coordinates are not world NED minus nothing carries the origin to add
// back in a header comment (`origin_ned_m N E D`). An optional crop box (NED, in the
// coordinates before the frame and the subtracted origin) keeps the triangles whose three
// vertices are inside it. A mission with a CRS (the grid its world frame is) has it in a
// header comment (`crs EPSG:32631`). `target_crs` writes world coordinates in another
// projected CRS through PROJ: x easting, y northing, z up (= -depth), in double (PLY, OBJ;
// STL refused), with that CRS and the mission origin in header comments (docs/formats.md,
// "Georeferenced export"). Every file is written to a temporary name and renamed: a failure
// keeps the previous file. An optional Progress gets the points or triangles placed (stage
// "export") and stops the export before anything is written when cancelled (Cancelled).
#pragma once

#include <Eigen/Geometry>
#include <filesystem>
#include <optional>
#include <string>

#include "mesh/seabed_grid.h"
#include "mesh/surface_mesher.h"
#include "occlusion/surface_points.h"

namespace sonarcarve {

class Progress;

struct ExportOptions {
  std::string format = "ply";  ///< ply | ply-ascii | stl | obj | las, geotiff (points)
  std::string frame = "ned";   ///< ned | zup
  Eigen::Vector3d origin_ned_m = Eigen::Vector3d::Zero();  ///< subtracted first
  std::optional<Eigen::AlignedBox3d> crop_ned_m;
  /// The origin the coordinates given are local to (the mission's): world = local + it.
  Eigen::Vector3d mission_origin_ned_m = Eigen::Vector3d::Zero();
  /// Write world coordinates: the mission origin added back, in double.
  bool add_mission_origin = false;
  /// The projected CRS whose grid the world frame is (the mission's); empty: none.
  std::string mission_crs;
  /// Write world coordinates in this projected CRS (easting, northing, up); empty: NED as above.
  std::string target_crs;
  void validate() const;
};

/// The format a file name asks for (.ply, .stl, .obj, .las, .tif/.tiff), or throws Error.
std::string formatOfPath(const std::filesystem::path& path);

void exportMesh(const Mesh& mesh, const std::filesystem::path& path, const ExportOptions& options,
                Progress* progress = nullptr);
/// Points as PLY (ply or ply-ascii) with intensity and views, or LAS (intensity rounded to
/// 16 bits, views in user data up to 255); other formats refused.
void exportPoints(const SurfacePoints& points, const std::filesystem::path& path,
                  const ExportOptions& options, Progress* progress = nullptr);
/// The seabed's elevation grid (mesh/seabed_grid.h) of the points as GeoTIFF (format
/// geotiff), x east(ing), y north(ing) as for LAS, with the CRS when there is one.
void exportSeabedGrid(const SurfacePoints& points, const std::filesystem::path& path,
                      const ExportOptions& options, const SeabedGridParams& grid,
                      Progress* progress = nullptr);
/// Reads a mesh written by exportMesh in PLY (any frame; no conversion back).
Mesh readMeshPly(const std::filesystem::path& path);

}  // namespace sonarcarve
