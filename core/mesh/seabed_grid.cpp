#include "mesh/seabed_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/error.h"

namespace sonarcarve {
namespace {

constexpr double kMaxCells = 2e8;
constexpr double kSurfaceVoxels = 3.0;
constexpr double kSlopeCells = 0.5;

// The height of the cell's seabed (steps 1 to 3 of the header), or NaN.
float cellHeight(std::vector<double>& heights, double band_m) {
  if (heights.size() < SeabedGridParams::kMinPoints) {
    return std::numeric_limits<float>::quiet_NaN();
  }
  std::sort(heights.begin(), heights.end());
  const auto low_index = static_cast<std::size_t>(
      std::floor(SeabedGridParams::kLowQuantile * static_cast<double>(heights.size() - 1)));
  const double top = heights[low_index] + band_m;
  const auto end = std::upper_bound(heights.begin(), heights.end(), top);
  const auto n = static_cast<std::size_t>(end - heights.begin());
  const double median = n % 2 == 1 ? heights[n / 2] : 0.5 * (heights[n / 2 - 1] + heights[n / 2]);
  return static_cast<float>(median);
}

}  // namespace

double SeabedGridParams::band_m() const {
  return std::max(kSurfaceVoxels * voxel_size_m, kSlopeCells * cell_m);
}

HeightRaster seabedGrid(const std::vector<Eigen::Vector3d>& points, const SeabedGridParams& p) {
  if (const auto problem = outsideRange(p.cell_m, SeabedGridParams::kCell)) {
    throw Error("export", "cell", "the edge of the seabed grid's cells: " + *problem);
  }
  HeightRaster raster;
  raster.cell_m = p.cell_m;
  if (points.empty()) {
    return raster;
  }
  Eigen::Vector2d lo = points.front().head<2>(), hi = lo;
  for (const Eigen::Vector3d& q : points) {
    lo = lo.cwiseMin(q.head<2>());
    hi = hi.cwiseMax(q.head<2>());
  }
  const double west = std::floor(lo.x() / p.cell_m), south = std::floor(lo.y() / p.cell_m);
  const double columns = std::floor(hi.x() / p.cell_m) - west + 1.0;
  const double rows = std::floor(hi.y() / p.cell_m) - south + 1.0;
  if (columns * rows > kMaxCells) {
    throw Error("export", "cell",
                "a cell of " + std::to_string(p.cell_m) + " m makes " +
                    std::to_string(columns * rows) +
                    " cells over the points: expected a larger cell (at most 2e8 cells)");
  }
  raster.width = static_cast<int>(columns);
  raster.height = static_cast<int>(rows);
  raster.west_m = west * p.cell_m;
  raster.north_m = (south + rows) * p.cell_m;
  std::vector<std::vector<double>> cells(static_cast<std::size_t>(columns * rows));
  for (const Eigen::Vector3d& q : points) {
    const auto column = static_cast<std::size_t>(std::floor(q.x() / p.cell_m) - west);
    const auto row_from_south = static_cast<std::size_t>(std::floor(q.y() / p.cell_m) - south);
    const std::size_t row = static_cast<std::size_t>(rows) - 1 - row_from_south;
    cells[row * static_cast<std::size_t>(columns) + column].push_back(q.z());
  }
  raster.values.reserve(cells.size());
  for (auto& heights : cells) {
    raster.values.push_back(cellHeight(heights, p.band_m()));
  }
  return raster;
}

}  // namespace sonarcarve
