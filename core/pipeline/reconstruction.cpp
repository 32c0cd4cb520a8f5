#include "pipeline/reconstruction.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>

#include "carve/carving_geometry.h"
#include "carve/fast_carver.h"
#include "carve/reference_carver.h"
#include "common/error.h"
#include "common/thread_pool.h"
#include "occlusion/occlusion_resolver.h"

namespace sonarcarve {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

struct PosedFrame {
  std::size_t index;
  Eigen::Isometry3d T_world_sonar;
};

// Blocks of `map` changed after stamp `since`, plus those `previous` (a map of the same
// region that `map` replaces) ever changed.
MapUpdate changedBlocks(const VoxelMap& map, std::uint32_t since, std::size_t frames_done,
                        const VoxelMap* previous = nullptr) {
  MapUpdate update;
  update.frames_done = frames_done;
  for (std::size_t b = 0; b < map.blockCount(); ++b) {
    if (map.stamp(b) <= since && (previous == nullptr || previous->stamp(b) == 0)) {
      continue;
    }
    MapBlockUpdate block;
    block.block = b;
    if (const float* v = map.values(b)) {
      for (int i = 0; i < VoxelMap::kBlockVoxels; ++i) {
        if (v[i] > 0.0f && v[i] < VoxelMap::kUnknown) {
          block.points.push_back(map.voxelCentre(map.voxelIndex(b, i)).cast<float>());
          block.values.push_back(v[i]);
        }
      }
    }
    update.blocks.push_back(std::move(block));
  }
  return update;
}

}  // namespace

std::vector<std::size_t> selectedFrames(const Mission& mission,
                                        const ReconstructionParams& params) {
  const std::size_t count = mission.frames.size();
  const std::size_t last =
      params.last_frame < 0 ? count : std::min(count, static_cast<std::size_t>(params.last_frame));
  std::vector<std::size_t> frames;
  for (std::size_t i = params.first_frame; i < last; i += params.stride) {
    frames.push_back(i);
  }
  return frames;
}

ReconstructionResult reconstruct(const Mission& mission, const ReconstructionParams& params,
                                 Progress& progress, ReconstructionObserver* observer,
                                 std::size_t update_every) {
  params.validate();
  const auto t_start = Clock::now();
  const SonarModel sonar = params.vertical_aperture_rad > 0.0
                               ? mission.sonar.withVerticalAperture(params.vertical_aperture_rad)
                               : mission.sonar;
  ReconstructionResult result;
  const Eigen::Isometry3d T_vehicle_sonar = mission.mounting.T_vehicle_sonar();
  const auto skip = [&](std::size_t index, const std::string& why) {
    result.skipped.push_back({index, why});
    if (observer) {
      observer->frameSkipped(result.skipped.back());
    }
  };

  // Poses first: frames outside the navigation cannot be placed and are skipped.
  std::vector<PosedFrame> posed;
  for (std::size_t i : selectedFrames(mission, params)) {
    const double t = mission.frames[i].time_s;
    if (!mission.nav.covers(t)) {
      skip(i, "frame " + std::to_string(i) + " at t = " + std::to_string(t) +
                  " s lies outside the navigation track");
      continue;
    }
    posed.push_back({i, mission.nav.T_world_sonar(t, T_vehicle_sonar)});
  }
  if (posed.empty()) {
    throw Error(mission.folder.string(), "", "no frame can be placed in the world");
  }

  // The map covers what the frames can see, within the region of interest.
  const CarvingGeometry geometry(sonar, params.carve);
  Eigen::AlignedBox3d bounds;
  for (const PosedFrame& f : posed) {
    bounds.extend(geometry.frustumBounds(f.T_world_sonar));
  }
  if (params.carve.region) {
    bounds = bounds.intersection(*params.carve.region);
  }
  if (bounds.isEmpty()) {
    throw Error("parameters", "region", "the region of interest is outside every frame's view");
  }
  CarveParams carve = params.carve;
  carve.region = bounds;
  // Noise removal before carving; detection probabilities are fused as log-odds.
  std::shared_ptr<const NoiseModel> noise_model;
  if (!params.noise_model.empty()) {
    noise_model = std::make_shared<const NoiseModel>(NoiseModel::load(params.noise_model));
  }
  const Detector detector(params.detector, noise_model, sonar);
  if (detector.params().mode == DetectorMode::Probability) {
    carve.fusion = CarveParams::Fusion::LogOdds;
    carve.intensity_threshold = 0.0;
  }
  const auto loadDetected = [&](std::size_t index) {
    Frame frame = loadFrame(mission, index);
    frame.image = detector.apply(frame.image);
    return frame;
  };

  std::vector<Eigen::Vector3i> occupied;
  std::vector<float> values;
  std::vector<PosedFrame> used;
  std::vector<double> carve_ms;
  std::unique_ptr<ReferenceCarver> reference;
  std::unique_ptr<FastCarver> fast;
  if (params.engine == Engine::Reference) {
    reference = std::make_unique<ReferenceCarver>(sonar, carve);
  } else {
    result.map = std::make_unique<VoxelMap>(carve.voxel_size_m, bounds);
    fast = std::make_unique<FastCarver>(*result.map, sonar, carve);
  }
  std::uint32_t last_update = 0;
  for (std::size_t n = 0; n < posed.size(); ++n) {
    if (progress.cancelled()) {
      result.cancelled = true;
      break;
    }
    const PosedFrame& f = posed[n];
    Frame frame;
    try {
      frame = loadDetected(f.index);
    } catch (const Error& e) {
      skip(f.index, e.what());
      continue;
    }
    const auto t0 = Clock::now();
    const auto stamp = static_cast<std::uint32_t>(n + 1);
    if (fast) {
      fast->integrate(frame.image, f.T_world_sonar, stamp);
    } else {
      reference->integrate(frame.image, f.T_world_sonar);
    }
    carve_ms.push_back(msSince(t0));
    used.push_back(f);
    if (observer) {
      observer->frameCarved(f.index, frame, f.T_world_sonar);
      if (fast &&
          (used.size() % std::max<std::size_t>(1, update_every) == 0 || n + 1 == posed.size())) {
        observer->mapUpdated(changedBlocks(*result.map, last_update, used.size()));
        last_update = stamp;
      }
    }
    progress.report("carve", n + 1, posed.size());
  }
  result.frames_used = used.size();
  if (used.empty()) {
    if (result.cancelled) {
      return result;
    }
    throw Error(mission.folder.string(), "", "every selected frame failed to load");
  }
  const auto collect = [&] {
    occupied.clear();
    values.clear();
    if (fast) {
      result.occupied_voxels = result.map->occupiedCount();
      result.map->forEachOccupiedOnShell([&](const Eigen::Vector3i& v, float value) {
        occupied.push_back(v);
        values.push_back(value);
      });
      result.map_bytes = result.map->memoryBytes();
    } else {
      occupied = reference->occupiedVoxels();
      result.occupied_voxels = occupied.size();
      for (const auto& v : occupied) {
        values.push_back(reference->value(v));
      }
      result.map_bytes = reference->memoryBytes();
    }
  };
  collect();

  // Occlusion-aware second carving: each frame carves only what it can see past the first
  // carving's surfaces, so shadowed surfaces keep the returns of the views that saw them.
  if (fast && params.occlusion_aware_carving && !result.cancelled) {
    const OcclusionResolver first_surface(occupied, values, sonar, carve);
    auto refined = std::make_unique<VoxelMap>(carve.voxel_size_m, bounds);
    FastCarver refine(*refined, sonar, carve);
    VisibilityLimit limit;
    limit.elevation_bins = first_surface.elevationBins();
    limit.elevation_step_rad = carve.elevation_step_rad;
    // The surface voxel itself and the range bin it falls in stay observable.
    limit.margin_m = std::sqrt(3.0) * carve.voxel_size_m + sonar.range().resolution_m;
    for (std::size_t n = 0; n < used.size() && !progress.cancelled(); ++n) {
      Frame frame;
      try {
        frame = loadDetected(used[n].index);
      } catch (const Error&) {
        continue;  // it loaded in the first pass; a file changed under us is skipped again
      }
      const std::vector<float> first = first_surface.firstReturnRanges(used[n].T_world_sonar);
      limit.first_return_m = &first;
      const auto t0 = Clock::now();
      refine.integrate(frame.image, used[n].T_world_sonar, static_cast<std::uint32_t>(n + 1),
                       limit);
      carve_ms[n] += msSince(t0);
      progress.report("refine", n + 1, used.size());
    }
    result.cancelled = progress.cancelled();
    if (observer) {
      // Every block either map touched: viewers replace what the first pass showed.
      observer->mapUpdated(changedBlocks(*refined, 0, used.size(), result.map.get()));
    }
    result.map = std::move(refined);
    collect();
  }
  std::sort(carve_ms.begin(), carve_ms.end());
  result.carve_ms_median = carve_ms[carve_ms.size() / 2];

  // Occlusion resolution: frames in parallel, cancellable between frames.
  const auto t_occlusion = Clock::now();
  OcclusionResolver resolver(occupied, values, sonar, carve);
  ThreadPool::shared().parallelFor(used.size(), 4, [&](std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i) {
      resolver.countObservations(used[i].T_world_sonar);
    }
  });
  resolver.requireObservations(params.min_views);
  std::atomic<std::size_t> resolved{0};
  ThreadPool::shared().parallelFor(used.size(), 1, [&](std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e && !progress.cancelled(); ++i) {
      resolver.addView(used[i].T_world_sonar);
      progress.report("occlusion", ++resolved, used.size());
    }
  });
  if (progress.cancelled()) {
    result.cancelled = true;
  }
  result.occlusion_ms_per_frame = msSince(t_occlusion) / static_cast<double>(used.size());
  result.surface = resolver.result(params.min_views);
  if (params.mesh_enabled && result.surface.size() >= 10 && !result.cancelled) {
    MeshParams mesh = params.mesh;
    mesh.voxel_size_m = carve.voxel_size_m;
    progress.report("mesh", 0, 1);
    result.mesh = meshSurface(result.surface, mesh);
    progress.report("mesh", 1, 1);
  }
  result.total_s = msSince(t_start) / 1000.0;
  return result;
}

}  // namespace sonarcarve
