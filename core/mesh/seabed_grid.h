// The seabed as a gridded elevation model: the surface points (x east(ing), y north(ing), z up,
// metres) binned into square cells aligned on multiples of the cell size, and per cell the
// height of the lowest surface seen there (docs/formats.md, "Seabed elevation (GeoTIFF)"):
//   1. low  = the cell's 10th percentile height: the lowest surface, past the few points a
//             noisy map leaves below it;
//   2. the cell's seabed points are those no higher than low + band, band = the larger of 3
//      voxels (the first-return surface's thickness) and half a cell (the rise of a 1:2 slope
//      across a cell); points above (a structure standing on the seabed) are not seabed;
//   3. height = the median of the seabed points' heights; a cell with fewer than 3 points has
//      no data (NaN).
// Where only a structure's top was seen (nothing under it), its top is the cell's height, as
// an echo sounder's would be.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "io/raster/geotiff_file.h"
#include "sonar/sonar_ranges.h"

namespace sonarcarve {

struct SeabedGridParams {
  double cell_m = 0.25;
  double voxel_size_m = 0.02;  ///< the reconstruction's voxel: the surface's thickness
  double band_m() const;
  static constexpr double kLowQuantile = 0.1;
  static constexpr std::size_t kMinPoints = 3;
  /// A cell's edge: a millimetre (under any voxel) to a kilometre (a whole survey in a few
  /// cells); 1e300 m wrote a raster whose corners were 1e300 m away, with exit 0.
  static constexpr PhysicalRange kCell{1e-3, 1000.0, "m"};
};

/// The grid over the points' box (cells of `params.cell_m`, edges on its multiples), heights
/// as above, no CRS (the caller sets it). Throws Error("export", "cell", ...) on a cell outside
/// SeabedGridParams::kCell or a grid over 2e8 cells.
HeightRaster seabedGrid(const std::vector<Eigen::Vector3d>& points_xyz_up,
                        const SeabedGridParams& params);

}  // namespace sonarcarve
