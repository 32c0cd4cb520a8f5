// mesh: the surface points' mesh (pipeline/surface_stage.h), unless meshing is off or the run
// was cancelled.
#include "pipeline/run_context.h"
#include "pipeline/stages/standard_stages.h"
#include "pipeline/surface_stage.h"

namespace sonarcarve {
namespace {

class MeshStage : public Stage {
 public:
  MeshStage() : Stage("mesh", 0.05) {}

  std::optional<MemoryNeed> memoryNeed(const RunContext& run) const override {
    const ReconstructionResult& result = run.result;
    if (!meshes(run)) {
      return std::nullopt;
    }
    const double map_held = result.carver ? static_cast<double>(result.carver->memoryBytes()) : 0.0;
    return MemoryNeed{
        {{"map", map_held},
         {"surface points", static_cast<double>(result.surface.size() * sizeof(SurfacePoint))},
         {"mesh", meshStageBytes(result.surface.size())}},
        "before the mesh"};
  }

  void run(RunContext& run, Progress& progress) const override {
    if (meshes(run)) {
      run.result.mesh =
          meshStage(run.result.surface, run.params.mesh, run.params.carve.voxel_size_m, progress);
    }
  }

 private:
  static bool meshes(const RunContext& run) {
    return run.params.mesh_enabled && !run.result.cancelled;
  }
};

}  // namespace

std::unique_ptr<Stage> makeMeshStage() {
  return std::make_unique<MeshStage>();
}

}  // namespace sonarcarve
