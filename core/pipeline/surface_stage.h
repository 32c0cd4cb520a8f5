// The last stages: occlusion resolution (the paper's first-return pass over every used frame,
// keeping voxels that are the first return in at least `min_views` views) and the mesh.
#pragma once

#include <vector>

#include "carve/carver.h"
#include "common/progress.h"
#include "mesh/surface_mesher.h"
#include "occlusion/surface_points.h"
#include "pipeline/frame_stage.h"

namespace sonarcarve {

struct SurfaceStageResult {
  SurfacePoints surface;
  double ms_per_frame = 0.0;
  bool cancelled = false;
};

/// Resolves occlusions in the carved map seen from `frames`, in parallel on `pool`,
/// cancellable between frames. `carve` are the parameters the map was carved with.
SurfaceStageResult resolveSurface(const Carver& carver, const std::vector<PosedFrame>& frames,
                                  const SonarModel& sonar, const CarveParams& carve,
                                  std::uint32_t min_views, ThreadPool& pool, Progress& progress);

/// The mesh of the surface points (empty when there are fewer than 10), with the map's voxel
/// size. Reports progress as the stage "mesh".
Mesh meshStage(const SurfacePoints& surface, MeshParams params, double voxel_size_m,
               Progress& progress);

}  // namespace sonarcarve
