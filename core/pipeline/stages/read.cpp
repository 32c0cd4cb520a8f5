// read: the selected frames that the navigation places (the others are skipped with the
// reason), the box the map covers (a region outside every view is an error before any frame
// is read) and the buffers the run will hold, checked against its memory budget.
#include "carve/occupancy_export.h"
#include "common/error.h"
#include "common/number_text.h"
#include "pipeline/run_context.h"
#include "pipeline/stages/standard_stages.h"

namespace sonarcarve {
namespace {

// map.bt holds the map only where OctoMap's 16-bit keys reach: a map beyond is carved and its
// other outputs written, but no map.bt (whose keys would wrap to the far side), and the run
// says so.
void noteOctoMapReach(RunContext& run) {
  const double voxel_m = run.params.carve.voxel_size_m;
  const std::optional<std::string> problem = octoMapKeyProblem(run.bounds, voxel_m);
  if (!problem) {
    return;
  }
  run.result.map_bt_skipped = *problem;
  RunChoice choice;
  choice.name = "map.bt";
  choice.value = "not written";
  choice.reason = *problem + "; the other outputs are written";
  choice.detail = "the map's box is [" + nedText(run.bounds.min()) + "] to [" +
                  nedText(run.bounds.max()) + "] m, local to the mission origin " +
                  nedText(run.mission.origin_ned_m) + " m";
  choice.action =
      "reconstruct a shorter part of the track (--first-frame, --last-frame) or "
      "use larger voxels to get a map.bt";
  choice.warning = true;
  run.choose(choice);
}

std::string timeSpan(double from_s, double to_s) {
  return "t = " + shortestNumber(from_s) + " to " + shortestNumber(to_s) + " s";
}

// A selection of frames that holds none is the parameters' fault, not the navigation's.
void requireSelectedFrames(const Mission& mission, const ReconstructionParams& p) {
  const std::size_t count = mission.frames.size();
  if (!selectFrames(count, frameSelection(p)).empty()) {
    return;
  }
  const std::string last = p.last_frame < 0 ? "the end" : std::to_string(p.last_frame);
  throw Error("parameters", "frames",
              "the selection from frame " + std::to_string(p.first_frame) + " to " + last +
                  " (exclusive) holds none of the mission's " + std::to_string(count) +
                  " frames: expected frames.first (--first-frame) below " + std::to_string(count) +
                  " and below frames.last (--last-frame)");
}

class ReadStage : public Stage {
 public:
  ReadStage() : Stage("read", 0.01) {}

  void run(RunContext& run, Progress&) const override {
    const ReconstructionParams& p = run.params;
    requireSelectedFrames(run.mission, p);
    run.posed = placeFrames(run.mission, frameSelection(p),
                            [&run](const FrameProblem& problem) { run.skip(problem); });
    if (run.posed.empty()) {
      throw Error(run.mission.folder.string(), "navigation",
                  "no selected frame lies within the navigation track (" +
                      timeSpan(run.mission.nav.startTime(), run.mission.nav.endTime()) +
                      "): expected frame times on the navigation's clock (--time-offset)");
    }
    run.carving = {p.engine,          p.carve,         p.occlusion_aware_carving,
                   p.pose_refinement, run.earlier_map, run.carve_frames};
    run.bounds = CarveStage(run.sonar, run.carving, run.pool).mapBounds(run.posed);
    // A run that lets finished blocks go holds the region in view, not the box: the least it
    // holds is one frame's, and its box is bounded only by the map's index (VoxelMap).
    const Eigen::AlignedBox3d held = run.evicting
                                         ? CarvingGeometry(run.sonar, run.carving.carve)
                                               .frustumBounds(run.posed.front().T_world_sonar)
                                               .intersection(run.bounds)
                                         : run.bounds;
    noteOctoMapReach(run);
    run.buffers = requireBoundedSizes(held.isEmpty() ? run.bounds : held, run.sonar, p.carve,
                                      run.pool.size(), run.memory.budget());
  }
};

}  // namespace

std::unique_ptr<Stage> makeReadStage() {
  return std::make_unique<ReadStage>();
}

}  // namespace sonarcarve
