// MapLod: the 3D view's copy of the carved map, held within a budget of points whatever the
// mission's length (level of detail). Each block of the map is held at a level: 0 keeps every
// occupied voxel; level k keeps one point per cell of 2^k voxels a side (cells of the map's own
// grid, so a cell never straddles two blocks) at the centroid of the voxels it stands for, with
// their mean value and error; kBlockLevel keeps one point for the whole block. When the points
// held pass the budget, the blocks changed longest ago (those the survey has left) are made
// coarser first, one level at a time, until the points held are back under nine tenths of it.
// A block that arrives again replaces what was held of it, at full detail; a block that arrives
// empty is dropped at whatever level it was held. Limits: one point per occupied block is the
// coarsest kept, so beyond `max_points` occupied blocks (about 12,800 m^2 of seabed at the
// default budget and 2 cm voxels) the points held grow with the blocks. Plain data, no Qt and no
// VTK; not thread safe.
#pragma once

#include <cstddef>
#include <map>
#include <vector>

#include "map_view_block.h"

namespace sonarcarve::widgets {

/// `block` with one point per cell of 2^level voxels a side (of the grid with a corner at the
/// world's origin), or one point for the whole block at MapLod::kBlockLevel and above: each at
/// the centroid of the voxels it stands for, with their mean value and mean error.
MapViewBlock coarsened(const MapViewBlock& block, int level, double voxel_size_m);

class MapLod {
 public:
  /// Points held at most (beyond one per occupied block), about 24 bytes each: 12 MB. The
  /// riser demo's map (at most 103,000 voxels) and the 1,500-frame riser orbit's (77,000) are
  /// held whole; the 3,990-frame seabed survey's (550,000) is not (docs/benchmarks.md).
  static constexpr std::size_t kDefaultMaxPoints = 500000;
  /// The level of one point per block: blocks of 8 voxels a side (VoxelMap::kBlockSide).
  static constexpr int kBlockLevel = 3;
  using Blocks = std::map<std::size_t, MapViewBlock>;

  explicit MapLod(std::size_t max_points = kDefaultMaxPoints, double voxel_size_m = 0.02);

  /// Sets the budget and makes blocks coarser now if the points held pass it.
  void setMaxPoints(std::size_t max_points);
  std::size_t maxPoints() const { return max_points_; }
  /// The map's voxel size, whose grid the coarser levels' cells follow (blocks held are kept).
  void setVoxelSize(double voxel_size_m) { voxel_size_m_ = voxel_size_m; }

  /// Applies a map update: each block replaces what was held of that block number, at full
  /// detail; one with no points is dropped. Then keeps the points held within the budget.
  void apply(std::vector<MapViewBlock> blocks);
  /// Gives the blocks held to the caller and holds none.
  [[nodiscard]] Blocks take();
  const Blocks& blocks() const { return blocks_; }

  /// Points held, over every block and level.
  std::size_t pointCount() const { return points_; }
  /// Occupied voxels those points stand for: every voxel received and not since carved.
  std::size_t voxelCount() const { return voxels_; }

 private:
  void keepWithinBudget();
  void setLevel(MapViewBlock& block, int level);

  Blocks blocks_;
  std::size_t max_points_;
  double voxel_size_m_;
  std::size_t points_ = 0;
  std::size_t voxels_ = 0;
};

}  // namespace sonarcarve::widgets
