// The one orchestrator of a reconstruction: mission frames -> carving -> occlusion resolution
// -> surface points, with progress, cancellation (checked between frames and inside long
// loops) and map updates for viewers. The GUI and the CLI both call reconstruct(); neither
// re-implements a step.
//
// Map updates: every `update_every` frames the observer receives, as values, the occupied
// voxels of each block that changed since the previous update (a block with no points has
// become empty). Together the updates always describe the map as carved so far, so a viewer
// that applies them in order shows a consistent map while it grows. Observer calls come from
// the thread running reconstruct().
#pragma once

#include <Eigen/Geometry>
#include <memory>
#include <vector>

#include "carve/voxel_map.h"
#include "common/progress.h"
#include "io/mission.h"
#include "mesh/surface_mesher.h"
#include "occlusion/surface_points.h"
#include "pipeline/reconstruction_params.h"

namespace sonarcarve {

struct MapBlockUpdate {
  std::size_t block = 0;
  std::vector<Eigen::Vector3f> points;  ///< occupied voxel centres, world NED
  std::vector<float> values;            ///< their carved intensities
};

struct MapUpdate {
  std::size_t frames_done = 0;
  std::vector<MapBlockUpdate> blocks;
};

class ReconstructionObserver {
 public:
  virtual ~ReconstructionObserver() = default;
  virtual void frameCarved(std::size_t /*frame_index*/, const Frame& /*frame*/,
                           const Eigen::Isometry3d& /*T_world_sonar*/) {}
  virtual void mapUpdated(const MapUpdate& /*update*/) {}
  virtual void frameSkipped(const FrameProblem& /*problem*/) {}
};

struct ReconstructionResult {
  SurfacePoints surface;
  Mesh mesh;                      ///< empty when meshing is off or there are too few points
  std::unique_ptr<VoxelMap> map;  ///< the carved map (fast engine)
  std::size_t frames_used = 0;
  std::vector<FrameProblem> skipped;
  bool cancelled = false;
  std::size_t occupied_voxels = 0;  ///< all occupied voxels of the carved map
  std::size_t map_bytes = 0;
  double carve_ms_median = 0.0;  ///< per frame
  double occlusion_ms_per_frame = 0.0;
  double total_s = 0.0;
};

/// Runs the reconstruction. Throws Error if no frame can be used; on cancellation returns
/// with `cancelled` set and whatever was finished.
ReconstructionResult reconstruct(const Mission& mission, const ReconstructionParams& params,
                                 Progress& progress, ReconstructionObserver* observer = nullptr,
                                 std::size_t update_every = 1);

/// Indices of the frames the parameters select (first, last, stride).
std::vector<std::size_t> selectedFrames(const Mission& mission, const ReconstructionParams& params);

}  // namespace sonarcarve
