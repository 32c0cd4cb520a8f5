// The run's memory budget (issue 18; docs/reliability.md, "Limits"): the user's
// memory_budget_mb or a share of the memory available; a run past it stops between frames with
// an Error that names the parameter and the figures, and a run within it is unchanged.
#include <gtest/gtest.h>

#include <cstdlib>

#include "common/error.h"
#include "pipeline/memory_budget.h"
#include "pipeline/reconstruction.h"
#include "pipeline/size_limits.h"
#include "sim/demo_scenes.h"
#include "sim/simulation_run.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

constexpr std::uint64_t kMiB = 1024 * 1024;

TEST(MemoryBudget, TheUsersFigureOrAShareOfTheMemoryAvailable) {
  const auto available = availableMemoryFrom("MemAvailable:  1024000 kB\n", "", "", "");
  auto budget = memoryBudget(0, available);
  ASSERT_TRUE(budget);
  EXPECT_EQ(budget->bytes, static_cast<std::uint64_t>(0.8 * 1024000 * 1024));
  EXPECT_EQ(budget->origin, "80 % of 1000 MiB available, MemAvailable in /proc/meminfo");
  budget = memoryBudget(0, availableMemoryFrom("MemAvailable:  1024000 kB\n", "", "", "512"));
  EXPECT_EQ(budget->bytes, static_cast<std::uint64_t>(0.8 * 512 * kMiB));
  EXPECT_EQ(budget->origin, "80 % of 512 MiB available, SONARCARVE_MEMORY_LIMIT_MB");
  budget = memoryBudget(3000, available);  // the user's figure, even above what is available
  EXPECT_EQ(budget->bytes, 3000 * kMiB);
  EXPECT_EQ(budget->origin, "memory_budget_mb");
  EXPECT_FALSE(memoryBudget(0, std::nullopt));
  EXPECT_EQ(memoryBudget(7, std::nullopt)->bytes, 7 * kMiB);
}

TEST(MemoryBudget, FiguresInMiBAndGiB) {
  EXPECT_EQ(memoryFigure(0.8 * kMiB), "0.8 MiB");
  EXPECT_EQ(memoryFigure(812.4 * kMiB), "812 MiB");
  EXPECT_EQ(memoryFigure(3.25 * 1024 * kMiB), "3.2 GiB");
}

TEST(MemoryWatch, StopsWhenWhatTheRunCountsOrTheProcessGrowthIsOverTheBudget) {
  std::uint64_t resident = 100 * kMiB;
  const MemoryWatch watch(MemoryBudget{50 * kMiB, "memory_budget_mb"},
                          [&] { return std::optional<std::uint64_t>(resident); });
  const std::vector<MemoryPart> small{{"map", 30.0 * kMiB}, {"frame buffers", 10.0 * kMiB}};
  EXPECT_NO_THROW(watch.require(small, "after frame 3 of 10"));
  resident = 170 * kMiB;  // 70 MiB more than at the start: something the parts do not count
  test::expectError([&] { watch.require(small, "after frame 4 of 10"); },
                    {"parameters: memory_budget_mb: the process has grown by 70 MiB since the "
                     "run began, after frame 4 of 10 (the run counts 40 MiB: map 30 MiB, frame "
                     "buffers 10 MiB), over the memory budget of 50 MiB (memory_budget_mb): set "
                     "memory_budget_mb, a region of interest (region), a larger voxel size"});
  resident = 90 * kMiB;
  const std::vector<MemoryPart> large{{"map", 45.0 * kMiB}, {"frame buffers", 10.0 * kMiB}};
  test::expectError([&] { watch.require(large, "after frame 5 of 10"); },
                    {"the run holds 55 MiB after frame 5 of 10 (map 45 MiB, frame buffers 10 "
                     "MiB), over the memory budget of 50 MiB",
                     "shard the mission (docs/scaling.md)"});
  const MemoryWatch unknown(std::nullopt);  // the memory available is not known
  EXPECT_NO_THROW(unknown.require(large, "after frame 5 of 10"));
}

ThreadPool& testPool() {
  static ThreadPool pool(2);
  return pool;
}

ReconstructionResult runPipeline(const Mission& mission, const ReconstructionParams& params,
                                 ReconstructionObserver* observer = nullptr) {
  SilentProgress progress;
  return Pipeline(mission, params, testPool()).run(progress, observer);
}

// What the run is estimated to hold before its map exists (size_limits.h).
double estimatedBytes(const Mission& mission, const ReconstructionParams& params) {
  const std::vector<PosedFrame> posed = placeFrames(
      mission, {params.first_frame, params.last_frame, params.stride}, [](const FrameProblem&) {});
  CarveStageParams stage;
  stage.carve = params.carve;
  const Eigen::AlignedBox3d bounds = CarveStage(mission.sonar, stage, testPool()).mapBounds(posed);
  return estimateMemory(bounds, mission.sonar, params.carve, testPool().size()).total();
}

struct FrameCounter : ReconstructionObserver {
  std::size_t carved = 0;
  void frameCarved(std::size_t, const Frame&, const Eigen::Isometry3d&) override { ++carved; }
};

// SONARCARVE_MEMORY_LIMIT_MB for the lifetime of the object.
class UserMemoryLimit {
 public:
  explicit UserMemoryLimit(const char* mb) { ::setenv("SONARCARVE_MEMORY_LIMIT_MB", mb, 1); }
  ~UserMemoryLimit() { ::unsetenv("SONARCARVE_MEMORY_LIMIT_MB"); }
  UserMemoryLimit(const UserMemoryLimit&) = delete;
  UserMemoryLimit& operator=(const UserMemoryLimit&) = delete;
};

class MemoryBudgetRun : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::ScratchDir();
    // A seabed seen from a lawnmower: its map outgrows the estimate made before carving.
    TrajectorySpec lawnmower;
    lawnmower.kind = "lawnmower";
    SimulationRequest request{makeDemoScene("seabed-objects"),
                              "seabed-objects",
                              paperSonar(),
                              lawnmower,
                              test::clippedBeam(),
                              NoiseSpec::none(),
                              NavErrorSpec{},
                              false,
                              kFrames,
                              dir_->path() / "seabed"};
    SilentProgress progress;
    ThreadPool pool;
    runSimulation(request, progress, pool);
  }
  static void TearDownTestSuite() { delete dir_; }
  static Mission mission() { return readMission(dir_->path() / "seabed"); }
  // Coarse voxels keep the runs short.
  static ReconstructionParams coarse() {
    ReconstructionParams params;
    params.carve.voxel_size_m = 0.03;
    return params;
  }
  static constexpr std::size_t kFrames = 8;
  static test::ScratchDir* dir_;
};
test::ScratchDir* MemoryBudgetRun::dir_ = nullptr;

TEST_F(MemoryBudgetRun, ATinyBudgetStopsTheRunAfterItsFirstFrames) {
  const Mission m = mission();
  ReconstructionParams params = coarse();
  params.mesh_enabled = false;
  const ReconstructionResult whole = runPipeline(m, params);
  // Between the estimate made before the map exists and what the map holds in the end.
  const double estimate = estimatedBytes(m, params);
  ASSERT_LT(estimate, 0.8 * static_cast<double>(whole.map_bytes));
  params.memory_budget_mb =
      static_cast<std::uint64_t>((estimate + static_cast<double>(whole.map_bytes)) / 2 / kMiB);
  FrameCounter counter;
  test::expectError([&] { runPipeline(m, params, &counter); },
                    {"parameters: memory_budget_mb: ", " after frame ", " of 8 (map ",
                     "over the memory budget of " + std::to_string(params.memory_budget_mb) +
                         " MiB (memory_budget_mb): set memory_budget_mb"});
  EXPECT_GE(counter.carved, 1u);
  EXPECT_LT(counter.carved, kFrames);
}

TEST_F(MemoryBudgetRun, TheDefaultBudgetIsAShareOfTheMemoryAvailable) {
  const UserMemoryLimit limit("1");
  test::expectError([&] { runPipeline(mission(), ReconstructionParams{}); },
                    {"parameters: voxel_size_m: the reconstruction needs at least",
                     "but the memory budget is 0.8 MiB (80 % of 1.0 MiB available, "
                     "SONARCARVE_MEMORY_LIMIT_MB)",
                     "or set memory_budget_mb"});
}

TEST_F(MemoryBudgetRun, ARunWithinItsBudgetIsUnchanged) {
  const Mission m = mission();
  ReconstructionParams params = coarse();
  const ReconstructionResult by_default = runPipeline(m, params);
  params.memory_budget_mb = 1024 * 1024;  // a terabyte: no check can stop it
  const ReconstructionResult roomy = runPipeline(m, params);
  EXPECT_EQ(by_default.frames_used, kFrames);
  EXPECT_EQ(by_default.map_bytes, roomy.map_bytes);
  EXPECT_EQ(by_default.occupied_voxels, roomy.occupied_voxels);
  ASSERT_EQ(by_default.surface.size(), roomy.surface.size());
  for (std::size_t i = 0; i < roomy.surface.size(); ++i) {
    EXPECT_EQ(by_default.surface[i].position_m, roomy.surface[i].position_m);
  }
  EXPECT_EQ(by_default.mesh.triangles.size(), roomy.mesh.triangles.size());
  EXPECT_GT(roomy.mesh.triangles.size(), 0u);
}

}  // namespace
}  // namespace sonarcarve
