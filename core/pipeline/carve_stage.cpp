#include "pipeline/carve_stage.h"

#include <chrono>
#include <cmath>

#include "carve/carving_geometry.h"
#include "carve/map_file.h"
#include "common/error.h"
#include "occlusion/occlusion_resolver.h"
#include "pipeline/size_limits.h"
#include "pipeline/track_refinement.h"
#include "sonar/mission_origin.h"

namespace sonarcarve {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

}  // namespace

CarveStage::CarveStage(const SonarModel& sonar, CarveStageParams params, ThreadPool& pool)
    : sonar_(sonar), params_(std::move(params)), pool_(pool) {}

Eigen::AlignedBox3d CarveStage::mapBounds(const std::vector<PosedFrame>& frames) const {
  const CarvingGeometry geometry(sonar_, params_.carve);
  Eigen::AlignedBox3d bounds;
  for (const PosedFrame& f : frames) {
    bounds.extend(geometry.frustumBounds(f.T_world_sonar));
  }
  if (params_.earlier_map) {
    bounds.extend(voxelCentresBox(*params_.earlier_map));
  }
  if (bounds.isEmpty()) {
    throw Error("carving", "map box",
                "the " + std::to_string(frames.size()) +
                    " frames' views span no volume: expected a sonar whose fan and range "
                    "window are not empty, and finite poses");
  }
  if (params_.carve.region) {
    const Eigen::AlignedBox3d viewed = bounds;
    bounds = bounds.intersection(*params_.carve.region);
    if (bounds.isEmpty()) {
      throw Error("parameters", "region",
                  "the region of interest [" + nedText(params_.carve.region->min()) + "] to [" +
                      nedText(params_.carve.region->max()) +
                      "] m is outside every frame's view (they span [" + nedText(viewed.min()) +
                      "] to [" + nedText(viewed.max()) +
                      "] m): expected a region that overlaps them");
    }
  }
  return bounds;
}

CarveStageResult CarveStage::run(const std::vector<PosedFrame>& frames,
                                 const Eigen::AlignedBox3d& bounds, const DenoisedFrames& source,
                                 Progress& progress, MapUpdateSink* updates,
                                 const std::function<void(const FrameProblem&)>& skip,
                                 const CarvedFrameCheck& check, const CarveHooks& hooks) const {
  CarveStageResult result;
  result.carve = params_.carve;
  result.carve.region = bounds;
  result.carver = makeCarver(params_.engine, CarverSetup{sonar_, result.carve, pool_});
  if (params_.earlier_map) {
    result.carver->fuse(*params_.earlier_map);
  }
  if (!params_.carve_frames) {
    result.used = frames;
    progress.report("carve", frames.size(), frames.size());
    return result;
  }
  std::vector<PoseCorrection> corrections;
  if (params_.refinement.enabled && result.carver->blockMap() != nullptr) {
    corrections = refineTrack(
        TrackRefinementSetup{sonar_, params_.engine, result.carve, params_.refinement, pool_},
        frames, source, progress);
    if (corrections.empty()) {
      result.cancelled = true;
      return result;
    }
  }
  for (std::size_t n = 0; n < frames.size(); ++n) {
    if (progress.cancelled()) {
      result.cancelled = true;
      break;
    }
    PosedFrame f = frames[n];
    if (hooks.starting) {
      hooks.starting(n, *result.carver);
    }
    Frame frame;
    BeforeDetection before;
    try {
      frame = source.load(f.index, result.carve.seabed_aware ? &before : nullptr);
    } catch (const Error& e) {
      skip({f.index, e.what()});
      continue;
    }
    const auto t0 = Clock::now();
    if (!corrections.empty()) {
      const FramePoseRefinement r{f.index, f.T_world_sonar, corrections[n]};
      f.T_world_sonar = r.correction.applied(r.T_world_sonar_prior);
      result.refinement.push_back(r);
    }
    const auto stamp = static_cast<std::uint32_t>(n + 1);
    result.carver->integrate(frame.image, f.T_world_sonar, stamp, {}, &before);
    result.carve_ms.push_back(msSince(t0));
    result.used.push_back(f);
    if (updates != nullptr) {
      updates->observer().frameCarved(f.index, frame, f.T_world_sonar);
      updates->frameDone(result.carver->blockMap(), result.used.size(), n + 1 == frames.size(),
                         stamp);
    }
    progress.report("carve", n + 1, frames.size());
    if (hooks.carved) {
      hooks.carved(n, f.T_world_sonar, *result.carver);
    }
    if (check) {
      check({"carving", n + 1, frames.size(), static_cast<double>(result.carver->memoryBytes())});
    }
  }
  if (params_.occlusion_aware && !result.cancelled && !result.used.empty() &&
      result.carver->supportsVisibilityLimit()) {
    refine(result, source, progress, updates, check);
  }
  return result;
}

void CarveStage::refine(CarveStageResult& result, const DenoisedFrames& source, Progress& progress,
                        MapUpdateSink* updates, const CarvedFrameCheck& check) const {
  const VoxelValues candidates = surfaceCandidates(*result.carver);
  const OcclusionResolver first_surface(candidates.voxels, candidates.values, sonar_, result.carve);
  auto refined = makeCarver(params_.engine, CarverSetup{sonar_, result.carve, pool_});
  if (params_.earlier_map) {
    refined->fuse(*params_.earlier_map);
  }
  VisibilityLimit limit;
  limit.elevation_bins = first_surface.elevationBins();
  limit.elevation_step_rad = result.carve.elevation_step_rad;
  // The surface voxel itself and the range bin it falls in stay observable.
  limit.margin_m = surfaceMargin(result.carve.voxel_size_m, sonar_.range().resolution_m);
  for (std::size_t n = 0; n < result.used.size() && !progress.cancelled(); ++n) {
    Frame frame;
    BeforeDetection before;
    try {
      frame = source.load(result.used[n].index, result.carve.seabed_aware ? &before : nullptr);
    } catch (const Error&) {
      continue;  // it loaded in the first pass; a file changed under us is skipped again
    }
    const std::vector<float> first = first_surface.firstReturnRanges(result.used[n].T_world_sonar);
    limit.first_return_m = &first;
    const auto t0 = Clock::now();
    refined->integrate(frame.image, result.used[n].T_world_sonar, static_cast<std::uint32_t>(n + 1),
                       limit, &before);
    result.carve_ms[n] += msSince(t0);
    progress.report("refine", n + 1, result.used.size());
    if (check) {
      check({"occlusion-aware carving", n + 1, result.used.size(),
             static_cast<double>(result.carver->memoryBytes() + refined->memoryBytes()) +
                 occlusionStageBytes(candidates.voxels.size())});
    }
  }
  result.cancelled = progress.cancelled();
  if (updates != nullptr && refined->blockMap() != nullptr) {
    updates->replaced(*refined->blockMap(), result.carver->blockMap(), result.used.size());
  }
  result.carver = std::move(refined);
}

}  // namespace sonarcarve
