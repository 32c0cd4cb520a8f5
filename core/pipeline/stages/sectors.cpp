// heading sectors: a mission that views the scene from several headings has each heading's
// frames carved as a pass of their own, and what each keeps that the mission's map lost set
// back (pipeline/heading_sectors.h, pipeline/sector_restore.h).
#include <cstdio>
#include <string>

#include "common/error.h"
#include "pipeline/heading_sectors.h"
#include "pipeline/run_context.h"
#include "pipeline/sector_restore.h"
#include "pipeline/shadow_carving.h"
#include "pipeline/stages/standard_stages.h"
#include "pipeline/surface_stage.h"

namespace sonarcarve {
namespace {

RunChoice sectorChoice(std::size_t sectors, std::size_t unswept, const SectorRestoreCount& count) {
  RunChoice choice;
  choice.name = "heading sectors";
  char value[64];
  std::snprintf(value, sizeof value, "%zu, %zu voxels set back", sectors, count.restored);
  choice.value = value;
  choice.reason =
      "the views come from several headings: each heading's frames were carved alone, and the "
      "surface each kept that views from other headings carved at grazing incidence was set "
      "back";
  choice.detail =
      std::to_string(unswept) +
      " voxels of the sectors' surfaces left out (their sector did not sweep its elevation beam "
      "over them), " +
      std::to_string(count.candidates) + " followed; " + std::to_string(count.vetoed) +
      " carved by another sector that looked at them within 45 degrees of their "
      "normal, " +
      std::to_string(count.no_normal) + " without enough surface around them to tell a normal; " +
      std::to_string(count.restored) + " of the others, carved by the mission's map, set back";
  return choice;
}

class SectorStage : public Stage {
 public:
  SectorStage() : Stage("heading sectors", 0.3) {}

  void run(RunContext& run, Progress& progress) const override {
    if (!run.params.heading_sectors || run.params.engine != Engine::Fast || run.evicting ||
        !run.carve_frames || run.earlier_map || run.result.cancelled || !run.result.carver) {
      return;
    }
    VoxelMap* mission_map = run.result.carver->evictableMap();
    const std::vector<std::vector<PosedFrame>> sectors =
        sectorsToCarve(run.carved.used, run.sonar.range().maxRange());
    if (mission_map == nullptr || sectors.empty()) {
      return;
    }
    CarveStageParams params = run.carving;
    params.occlusion_aware = false;
    params.refinement.enabled = false;
    RenamedProgress carving(progress, "heading sectors");
    std::vector<std::unique_ptr<Carver>> carvers;
    std::vector<SectorCarve> carves;
    std::size_t unswept = 0;
    for (const std::vector<PosedFrame>& frames : sectors) {
      // A sector looks one way: its shadows fall where its own views do not look.
      params.carve.shadow_aware = chooseShadowCarving(run.params.shadow_aware_carving, frames).on;
      const CarveStage stage(run.sonar, params, run.pool);
      CarveStageResult carved = stage.run(frames, stage.mapBounds(frames), *run.frames, carving,
                                          nullptr, [](const FrameProblem&) {});
      if (carved.cancelled) {
        throw Cancelled();
      }
      SurfaceStageResult surface =
          resolveSurface(*carved.carver, carved.used, run.sonar, carved.carve, run.params.min_views,
                         run.pool, carving);
      if (surface.cancelled) {
        throw Cancelled();
      }
      SectorCarve& carve = carves.emplace_back();
      carve.map = carved.carver->blockMap();
      const std::vector<bool> swept =
          elevationSwept(surface.surface, carved.used, run.sonar,
                         kSweptApertureShare * run.sonar.verticalAperture());
      for (std::size_t p = 0; p < swept.size(); ++p) {
        if (swept[p]) {
          carve.surface.push_back(surface.surface[p]);
        } else {
          ++unswept;
        }
      }
      for (const PosedFrame& frame : carved.used) {
        carve.centre += frame.T_world_sonar.translation();
      }
      carve.centre /= static_cast<double>(std::max<std::size_t>(1, carved.used.size()));
      carvers.push_back(std::move(carved.carver));
      double sector_bytes = 0.0;
      for (const auto& carver : carvers) {
        sector_bytes += static_cast<double>(carver->memoryBytes());
      }
      run.memory.require({{"map", static_cast<double>(mission_map->memoryBytes())},
                          {"heading sectors' maps", sector_bytes}},
                         "after heading sector " + std::to_string(carvers.size()) + " of " +
                             std::to_string(sectors.size()));
    }
    run.choose(sectorChoice(sectors.size(), unswept, restoreSectorSurfaces(*mission_map, carves)));
  }
};

}  // namespace

std::unique_ptr<Stage> makeSectorStage() {
  return std::make_unique<SectorStage>();
}

}  // namespace sonarcarve
