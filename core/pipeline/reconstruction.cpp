#include "pipeline/reconstruction.h"

#include <algorithm>
#include <chrono>
#include <optional>

#include "carve/carving_geometry.h"
#include "common/available_memory.h"
#include "common/error.h"
#include "denoise/noise_model.h"
#include "pipeline/carve_stage.h"
#include "pipeline/evicting_surface.h"
#include "pipeline/frame_stage.h"
#include "pipeline/memory_budget.h"
#include "pipeline/shadow_carving.h"
#include "pipeline/size_limits.h"
#include "pipeline/surface_stage.h"

namespace sonarcarve {
namespace {

// Seabed-aware carving in words: off and why, or in how many frames a seabed explained.
std::string describeSeabedCarving(const ReconstructionParams& params, bool beam_aware,
                                  std::size_t seabed_frames, std::size_t frames) {
  if (params.engine != Engine::Fast) {
    return "off (the reference engine)";
  }
  if (!params.carve.seabed_aware) {
    return "off (seabed_aware_carving: false)";
  }
  if (!beam_aware) {
    return "off (it needs beam-aware carving on a sinc^2 beam)";
  }
  return "on, a seabed explained " + std::to_string(seabed_frames) + " of " +
         std::to_string(frames) + " frames";
}

FrameSelection selectionOf(const ReconstructionParams& params) {
  return {params.first_frame, params.last_frame, params.stride};
}

const ReconstructionParams& validated(const ReconstructionParams& params) {
  params.validate();
  return params;
}

}  // namespace

SonarModel carvingSonar(const Mission& mission, const ReconstructionParams& params) {
  SonarModel sonar = params.vertical_aperture_rad > 0.0
                         ? mission.sonar.withVerticalAperture(params.vertical_aperture_rad)
                         : mission.sonar;
  return params.horizontal_beam_width_rad > 0.0
             ? sonar.withHorizontalBeamWidth(params.horizontal_beam_width_rad)
             : sonar;
}

std::vector<std::size_t> selectedFrames(const Mission& mission,
                                        const ReconstructionParams& params) {
  return selectFrames(mission.frames.size(), selectionOf(params));
}

std::vector<std::size_t> placedFrames(const Mission& mission, const ReconstructionParams& params) {
  return indicesOf(placeFrames(mission, selectionOf(params), [](const FrameProblem&) {}));
}

Pipeline::Pipeline(const Mission& mission, ReconstructionParams params, ThreadPool& pool)
    : mission_(mission),
      params_(validated(params)),
      sonar_(carvingSonar(mission, params_)),
      noise_model_(params_.noise_model.empty()
                       ? nullptr
                       : std::make_shared<const NoiseModel>(NoiseModel::load(params_.noise_model))),
      pool_(pool) {}

bool Pipeline::evicts() const {
  return params_.evict_blocks && params_.engine == Engine::Fast && !earlier_map_ && carve_frames_ &&
         !keep_whole_map_ && !params_.occlusion_aware_carving && !params_.pose_refinement.enabled;
}

ReconstructionResult Pipeline::run(Progress& progress, ReconstructionObserver* observer,
                                   std::size_t update_every) const {
  const auto t_start = std::chrono::steady_clock::now();
  ReconstructionResult result;
  const auto skip = [&](const FrameProblem& problem) {
    result.skipped.push_back(problem);
    if (observer) {
      observer->frameSkipped(problem);
    }
  };

  // Read: frames outside the navigation cannot be placed and are skipped.
  const std::vector<PosedFrame> posed = placeFrames(mission_, selectionOf(params_), skip);
  if (posed.empty()) {
    throw Error(mission_.folder.string(), "", "no frame can be placed in the world");
  }
  // Denoise, then carve.
  CarveStageParams stage{params_.engine,          params_.carve, params_.occlusion_aware_carving,
                         params_.pose_refinement, earlier_map_,  carve_frames_};
  if (params_.engine == Engine::Fast) {
    const ShadowCarvingChoice shadow = chooseShadowCarving(params_.shadow_aware_carving, posed);
    stage.carve.shadow_aware = shadow.on;
    result.shadow_carving = shadow.reason;
  }
  // A region outside every view is an error before any frame is read.
  const Eigen::AlignedBox3d bounds = CarveStage(sonar_, stage, pool_).mapBounds(posed);
  const MemoryWatch memory(memoryBudget(params_.memory_budget_mb, availableMemory()));
  // A run that lets finished blocks go holds the region in view, not the box: the least it
  // holds is one frame's, and its box is bounded only by the map's index (VoxelMap).
  const bool evicting_run = evicts() && observer == nullptr;
  const Eigen::AlignedBox3d held = evicting_run ? CarvingGeometry(sonar_, stage.carve)
                                                      .frustumBounds(posed.front().T_world_sonar)
                                                      .intersection(bounds)
                                                : bounds;
  const MemoryEstimate buffers = requireBoundedSizes(held.isEmpty() ? bounds : held, sonar_,
                                                     params_.carve, pool_.size(), memory.budget());
  const std::string threads = " of " + std::to_string(pool_.size()) + " threads";
  NoiseChoice noise;
  try {
    noise = chooseNoiseModel(mission_, posed, params_.detector, params_.noise_model, noise_model_,
                             progress);
  } catch (const Cancelled&) {
    result.cancelled = true;
    return result;
  }
  result.detector = std::string(toString(noise.detector.mode));
  result.denoising = noise.reason;
  if (observer) {
    observer->noiseModelChosen(noise.model);
  }
  // Beams wider than their spacing blur each row across bearing: taken out of the frames,
  // with the width the sonar declares or, failing that, one read from the frames.
  // A run that reads no frame (startFrom without carving) reads none for it either.
  std::optional<BeamWidthChoice> beams;
  try {
    beams = carve_frames_ ? chooseBeamWidth(mission_, sonar_, indicesOf(posed), progress)
                          : BeamWidthChoice{sonar_, ""};
  } catch (const Cancelled&) {
    result.cancelled = true;
    return result;
  }
  const DenoisedFrames frames(mission_, beams->sonar, noise);
  result.bearing_deblur =
      beams->sonar.horizontalBeamWidth() > 0.0
          ? frames.bearingDeblur() + (beams->reason.empty() ? "" : "; " + beams->reason)
          : "off: " + beams->reason;
  // The keep level bounds what frames carve: a run that only resolves a loaded map's surface
  // (startFrom without carving) reads no frame for it.
  if (carvesMainLobe(sonar_, stage.carve) && carve_frames_) {
    try {
      result.keep_level = measureKeepLevel(frames, posed, stage.carve.dynamic_range_db, progress);
    } catch (const Cancelled&) {
      result.cancelled = true;
      return result;
    }
    stage.carve.keep_level = result.keep_level.level;
    result.keep_level.unit = sonar_.intensityScale().isLinear() ? "counts" : "power";
    stage.carve.dark_pixels = darkPixelsAreExact(noise.detector)
                                  ? CarveParams::DarkPixels::Exact
                                  : CarveParams::DarkPixels::BelowDetection;
    stage.carve.dark_pixel_level = sonar_.intensityScale().darkPower();
    const double used = effectiveKeepLevel(stage.carve);
    result.keep_level.raised_to_a_count = used > stage.carve.keep_level;
    result.keep_level.level = stage.carve.keep_level = used;
  }
  const CarveStage carving(sonar_, stage, pool_);
  std::optional<MapUpdateSink> updates;
  if (observer) {
    updates.emplace(*observer, update_every);
  }
  const auto check_frame = [&](const CarvedSoFar& at) {
    std::vector<MemoryPart> parts{{"map", at.map_bytes},
                                  {"frame buffers" + threads, buffers.frames}};
    std::string when =
        "after frame " + std::to_string(at.frame) + " of " + std::to_string(at.frames);
    if (at.pass != "carving") {
      parts.push_back({"z-buffers" + threads, buffers.occlusion});
      when += " of " + std::string(at.pass);
    }
    memory.require(parts, when);
  };
  // The mesh of the surface, last.
  const auto finish = [&] {
    if (params_.mesh_enabled && !result.cancelled) {
      const double map_held =
          result.carver ? static_cast<double>(result.carver->memoryBytes()) : 0.0;
      memory.require(
          {{"map", map_held},
           {"surface points", static_cast<double>(result.surface.size() * sizeof(SurfacePoint))},
           {"mesh", meshStageBytes(result.surface.size())}},
          "before the mesh");
      result.mesh = meshStage(result.surface, params_.mesh, params_.carve.voxel_size_m, progress);
    }
    result.total_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  };
  // A map viewer shows the whole map: it is kept then.
  std::optional<EvictingSurface> evicting;
  CarveHooks hooks;
  if (evicting_run) {
    CarveParams as_carved = stage.carve;
    as_carved.region = bounds;
    evicting.emplace(posed, sonar_, as_carved, params_.min_views, pool_,
                     params_.set_aside_after_frames);
    hooks.starting = [&](std::size_t position, Carver& carver) {
      evicting->frameStarting(position, *carver.evictableMap());
    };
    hooks.carved = [&](std::size_t position, const Eigen::Isometry3d& T_world_sonar,
                       Carver& carver) {
      evicting->frameCarved(position, T_world_sonar, *carver.evictableMap());
    };
  }
  CarveStageResult carved = carving.run(posed, bounds, frames, progress,
                                        updates ? &*updates : nullptr, skip, check_frame, hooks);
  result.cancelled = carved.cancelled;
  result.frames_used = carved.used.size();
  result.refinement = std::move(carved.refinement);
  if (carved.used.empty()) {
    if (result.cancelled) {
      return result;
    }
    throw Error(mission_.folder.string(), "", "every selected frame failed to load");
  }
  result.carver = std::move(carved.carver);
  result.seabed_carving =
      describeSeabedCarving(params_, carvesMainLobe(sonar_, stage.carve),
                            result.carver->stats().seabed_frames, carved.used.size());
  std::sort(carved.carve_ms.begin(), carved.carve_ms.end());
  result.carve_ms_median =
      carved.carve_ms.empty() ? 0.0 : carved.carve_ms[carved.carve_ms.size() / 2];
  if (evicting) {
    if (!result.cancelled) {
      evicting->finish(*result.carver->evictableMap());
    }
    result.evicted = true;
    result.pages_freed_early = evicting->pagesFreedEarly();
    result.pages_set_aside = evicting->pagesSetAside();
    result.aside_file_bytes = evicting->asideFileBytes();
    result.temporary_file_problem = evicting->temporaryFileProblem();
    result.surface = evicting->surface();
    result.occupancy = evicting->takeOccupancy();
    result.occupied_voxels = evicting->occupiedVoxels();
    result.map_bytes = evicting->peakBytes();
    result.occlusion_ms_per_frame =
        evicting->occlusionMs() / static_cast<double>(std::max<std::size_t>(1, posed.size()));
    progress.report("occlusion", posed.size(), posed.size());
    finish();
    return result;
  }
  result.map = result.carver->blockMap();
  const CarverStats stats = result.carver->stats();
  result.occupied_voxels = stats.occupied_voxels;
  result.map_bytes = stats.memory_bytes;

  // Occlusion resolution and the surface.
  const auto map_bytes = static_cast<double>(result.map_bytes);
  memory.require({{"map", map_bytes},
                  {"occlusion resolution", occlusionStageBytes(result.occupied_voxels)},
                  {"z-buffers" + threads, buffers.occlusion}},
                 "before occlusion resolution");
  SurfaceStageResult surface = resolveSurface(*result.carver, carved.used, sonar_, carved.carve,
                                              params_.min_views, pool_, progress);
  result.cancelled = result.cancelled || surface.cancelled;
  result.occlusion_ms_per_frame = surface.ms_per_frame;
  result.surface = std::move(surface.surface);
  finish();
  return result;
}

}  // namespace sonarcarve
