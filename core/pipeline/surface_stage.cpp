#include "pipeline/surface_stage.h"

#include <atomic>
#include <chrono>

#include "occlusion/occlusion_resolver.h"

namespace sonarcarve {

SurfaceStageResult resolveSurface(const Carver& carver, const std::vector<PosedFrame>& frames,
                                  const SonarModel& sonar, const CarveParams& carve,
                                  std::uint32_t min_views, ThreadPool& pool, Progress& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  const VoxelValues candidates = surfaceCandidates(carver);
  OcclusionResolver resolver(candidates.voxels, candidates.values, sonar, carve);
  pool.parallelFor(frames.size(), 4, [&](std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i) {
      resolver.countObservations(frames[i].T_world_sonar);
    }
  });
  resolver.requireObservations(min_views);
  std::atomic<std::size_t> resolved{0};
  pool.parallelFor(frames.size(), 1, [&](std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e && !progress.cancelled(); ++i) {
      resolver.addView(frames[i].T_world_sonar);
      progress.report("occlusion", ++resolved, frames.size());
    }
  });
  SurfaceStageResult result;
  result.cancelled = progress.cancelled();
  result.ms_per_frame =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count() /
      static_cast<double>(std::max<std::size_t>(1, frames.size()));
  result.surface = resolver.result(min_views);
  return result;
}

Mesh meshStage(const SurfacePoints& surface, MeshParams params, double voxel_size_m,
               Progress& progress) {
  if (surface.size() < 10) {
    return {};
  }
  params.voxel_size_m = voxel_size_m;
  progress.report("mesh", 0, 1);
  Mesh mesh = meshSurface(surface, params);
  progress.report("mesh", 1, 1);
  return mesh;
}

}  // namespace sonarcarve
