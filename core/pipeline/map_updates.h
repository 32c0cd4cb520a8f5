// Map updates for viewers while the map grows: every `every` frames the observer receives, as
// values, the occupied voxels of each block that changed since the previous update (a block
// with no points has become empty). Applied in order, the updates always describe the map as
// carved so far.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <vector>

#include "carve/voxel_map.h"
#include "io/mission/mission.h"
#include "sonar/frame.h"

namespace sonarcarve {

class NoiseModel;

struct MapBlockUpdate {
  std::size_t block = 0;
  std::vector<Eigen::Vector3f> points;  ///< occupied voxel centres, world NED
  std::vector<float> values;            ///< their carved intensities
};

struct MapUpdate {
  std::size_t frames_done = 0;
  std::vector<MapBlockUpdate> blocks;
};

/// What a viewer hears of a reconstruction. Calls come from the thread running it.
class ReconstructionObserver {
 public:
  virtual ~ReconstructionObserver() = default;
  virtual void frameCarved(std::size_t /*frame_index*/, const Frame& /*frame*/,
                           const Eigen::Isometry3d& /*T_world_sonar*/) {}
  virtual void mapUpdated(const MapUpdate& /*update*/) {}
  virtual void frameSkipped(const FrameProblem& /*problem*/) {}
  /// The noise model the run's detector uses, given or learned from the mission's frames
  /// (null: none), before any frame is carved.
  virtual void noiseModelChosen(const std::shared_ptr<const NoiseModel>& /*model*/) {}
};

/// Blocks of `map` changed after stamp `since`, plus those `previous` (a map of the same
/// region that `map` replaces) ever changed.
MapUpdate changedBlocks(const VoxelMap& map, std::uint32_t since, std::size_t frames_done,
                        const VoxelMap* previous = nullptr);

/// Sends a carving engine's changes to an observer every `every` frames.
class MapUpdateSink {
 public:
  MapUpdateSink(ReconstructionObserver& observer, std::size_t every)
      : observer_(observer), every_(every == 0 ? 1 : every) {}
  ReconstructionObserver& observer() { return observer_; }
  /// After `done` frames carved, the latest with `stamp`; `last`: no frame follows.
  void frameDone(const VoxelMap* map, std::size_t done, bool last, std::uint32_t stamp);
  /// The map `map` replaces `previous` (a second pass): every block either touched.
  void replaced(const VoxelMap& map, const VoxelMap* previous, std::size_t frames_done);

 private:
  ReconstructionObserver& observer_;
  std::size_t every_;
  std::uint32_t last_stamp_ = 0;
};

}  // namespace sonarcarve
