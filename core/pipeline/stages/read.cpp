// read: the selected frames that the navigation places (the others are skipped with the
// reason), the box the map covers (a region outside every view is an error before any frame
// is read) and the buffers the run will hold, checked against its memory budget.
#include "common/error.h"
#include "pipeline/run_context.h"
#include "pipeline/stages/standard_stages.h"

namespace sonarcarve {
namespace {

class ReadStage : public Stage {
 public:
  ReadStage() : Stage("read", 0.01) {}

  void run(RunContext& run, Progress&) const override {
    const ReconstructionParams& p = run.params;
    run.posed = placeFrames(run.mission, frameSelection(p),
                            [&run](const FrameProblem& problem) { run.skip(problem); });
    if (run.posed.empty()) {
      throw Error(run.mission.folder.string(), "", "no frame can be placed in the world");
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
    run.buffers = requireBoundedSizes(held.isEmpty() ? run.bounds : held, run.sonar, p.carve,
                                      run.pool.size(), run.memory.budget());
  }
};

}  // namespace

std::unique_ptr<Stage> makeReadStage() {
  return std::make_unique<ReadStage>();
}

}  // namespace sonarcarve
