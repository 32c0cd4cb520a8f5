// A run that lets finished blocks go (evict_blocks, pipeline/evicting_surface.h) gives the
// in-memory run's outputs: the same surface points (position, intensity, views), the same mesh
// and the same map.bt, on a lawnmower of two lines over the seabed field, where the first
// line's blocks go while the second is flown (and where pages the second line comes back to
// are set aside in a file meanwhile), and on the riser.
#include <gtest/gtest.h>

#include "carve/occupancy_export.h"
#include "common/angles.h"
#include "pipeline/reconstruction.h"
#include "sim/demo_scenes.h"
#include "sim/seabed_field.h"
#include "sim/simulation_run.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

struct Outputs {
  ReconstructionResult result;
  std::string bt;
};

Outputs reconstruct(const std::filesystem::path& mission_folder, bool evict,
                    const std::filesystem::path& bt, std::int32_t set_aside_after_frames) {
  static ThreadPool pool(2);
  const Mission mission = readMission(mission_folder);
  ReconstructionParams params;
  params.evict_blocks = evict;
  params.set_aside_after_frames = set_aside_after_frames;
  SilentProgress progress;
  Outputs out{sonarcarve::Pipeline(mission, params, pool).run(progress), {}};
  if (out.result.evicted) {
    writeOccupancyBt(out.result.occupancy.sorted(), params.carve.voxel_size_m, bt);
  } else {
    writeOccupancyBt(*out.result.map, bt);
  }
  out.bt = test::readText(bt);
  return out;
}

// The evicting run's result, after comparing it with the in-memory run's.
ReconstructionResult expectSameOutputs(const std::filesystem::path& mission,
                                       const test::ScratchDir& dir,
                                       std::int32_t set_aside_after_frames = 100) {
  const Outputs kept = reconstruct(mission, false, dir.path() / "kept.bt", 0);
  Outputs evicted = reconstruct(mission, true, dir.path() / "evicted.bt", set_aside_after_frames);
  EXPECT_FALSE(kept.result.evicted);
  EXPECT_TRUE(evicted.result.evicted);
  EXPECT_GT(kept.result.surface.size(), 10u);
  EXPECT_EQ(evicted.result.surface.size(), kept.result.surface.size());
  if (evicted.result.surface.size() != kept.result.surface.size()) {
    return {};
  }
  for (std::size_t i = 0; i < kept.result.surface.size(); ++i) {
    const SurfacePoint& a = kept.result.surface[i];
    const SurfacePoint& b = evicted.result.surface[i];
    EXPECT_EQ(a.position_m, b.position_m) << "point " << i;
    EXPECT_EQ(a.intensity, b.intensity) << "point " << i;
    EXPECT_EQ(a.views, b.views) << "point " << i;
  }
  EXPECT_EQ(evicted.result.occupied_voxels, kept.result.occupied_voxels);
  EXPECT_EQ(evicted.result.mesh.vertices, kept.result.mesh.vertices);
  EXPECT_EQ(evicted.result.mesh.triangles, kept.result.mesh.triangles);
  EXPECT_TRUE(evicted.bt == kept.bt) << "map.bt differs";
  return std::move(evicted.result);
}

TEST(Eviction, ALawnmowerGivesTheSameOutputsAndLetsItsFirstLineGo) {
  test::ScratchDir dir;
  TrajectorySpec trajectory;
  trajectory.kind = "lawnmower";
  trajectory.line_length_m = 15.0;  // longer than the 10 m reach: a line leaves cells behind
  trajectory.line_spacing_m = 5.0;
  trajectory.step_m = 0.5;
  trajectory.speed_mps = 5.0;  // 10 frames a second
  trajectory.frames = 64;      // two lines and the turn
  ImagingSettings imaging = test::clippedBeam();
  imaging.elevation_step_rad = degToRad(1.0);
  SimulationRequest request{Scene{},      "seabed-field",     paperSonar(),   trajectory,
                            imaging,      NoiseSpec::none(),  NavErrorSpec{}, false,
                            std::nullopt, dir.path() / "lawn"};
  SilentProgress progress;
  ThreadPool pool;
  runSimulation(request, progress, pool, SeabedFieldSpec{});
  // Pages the second line comes back to are set aside in a file meanwhile (here after 5
  // frames away: the first line's start is out of reach for about 20 frames) and held again
  // as they were. The riser's run below sets nothing aside.
  const ReconstructionResult evicted = expectSameOutputs(dir.path() / "lawn", dir, 5);
  EXPECT_GT(evicted.pages_freed_early, 0u);
  EXPECT_GT(evicted.pages_set_aside, 0u);
  EXPECT_GT(evicted.aside_file_bytes, 0u);
}

TEST(Eviction, TheRiserGivesTheSameOutputs) {
  test::ScratchDir dir;
  TrajectorySpec trajectory;
  SimulationRequest request{
      makeDemoScene("riser"), "riser",        paperSonar(), trajectory, test::clippedBeam(),
      NoiseSpec::none(),      NavErrorSpec{}, false,        24,         dir.path() / "riser"};
  SilentProgress progress;
  ThreadPool pool;
  runSimulation(request, progress, pool);
  EXPECT_EQ(expectSameOutputs(dir.path() / "riser", dir).pages_set_aside, 0u);
}

}  // namespace
}  // namespace sonarcarve
