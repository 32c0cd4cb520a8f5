// The simulator end to end on a few frames: a readable mission plus its ground truth.
#include <gtest/gtest.h>

#include "common/error.h"
#include "geometry/scene_io.h"
#include "io/mission/mission.h"
#include "sim/demo_scenes.h"
#include "sim/simulation_run.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

SimulationRequest riserRequest(const std::filesystem::path& out) {
  TrajectorySpec trajectory;
  trajectory.kind = "vertical";
  return SimulationRequest{makeDemoScene("riser"),
                           "riser",
                           paperSonar(),
                           trajectory,
                           test::clippedBeam(),
                           NoiseSpec{},
                           NavErrorSpec{},
                           false,
                           12,  // from 1 m above the riser's top to its first module
                           out};
}

// Cancels after a given number of progress reports.
class CancelAfter : public Progress {
 public:
  explicit CancelAfter(std::size_t reports) : left_(reports) {}
  void report(const std::string&, std::size_t, std::size_t) override {
    if (left_ > 0) {
      --left_;
    }
  }
  bool cancelled() const override { return left_ == 0; }

 private:
  std::size_t left_;
};

TEST(SimulationRun, WritesAMissionWithGroundTruth) {
  test::ScratchDir dir;
  SilentProgress progress;
  SimulationRequest request = riserRequest(dir.path() / "riser");
  request.nav_error = {0.01, 0.1, 3};
  ThreadPool pool;
  const SimulationResult result = runSimulation(request, progress, pool);
  EXPECT_EQ(result.frames_written, 12u);
  EXPECT_FALSE(result.cancelled);
  const Mission mission = readMission(dir.path() / "riser");
  EXPECT_EQ(mission.frames.size(), 12u);
  EXPECT_TRUE(checkFrames(mission).empty());
  EXPECT_EQ(mission.sonar.cols(), 650);
  // The recorded navigation carries the error; the ground-truth poses do not.
  const NavTrack truth = readMission(dir.path() / "riser").nav;
  for (const char* file :
       {"ground_truth.ply", "ground_truth_poses.csv", "visible_points.ply", "simulation.yaml"}) {
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "riser" / file)) << file;
  }
  const Scene gt = loadSceneMesh(dir.path() / "riser" / "ground_truth.ply");
  EXPECT_EQ(gt.triangles.size(), request.scene.triangles.size());
  // Visible points lie on the riser's front: within the pipe or module radii of its axis.
  const auto visible = readPointsPly(dir.path() / "riser" / "visible_points.ply");
  ASSERT_GT(visible.size(), 1000u);
  EXPECT_EQ(visible.size(), result.visible_points);
  for (const auto& p : visible) {
    const double radial = std::hypot(p.x(), p.y());
    const bool on_pipe_or_module = radial < 0.46;
    const bool on_seabed_or_cable = p.z() > 14.4;
    ASSERT_TRUE(on_pipe_or_module || on_seabed_or_cable) << p.transpose();
    if (p.z() > 9.51 && p.z() < 14.4) {
      // Below the top cap (seen from above) and above the cables, pipe and modules are seen
      // from 4.5 m south: only their south side, up to the
      // tangent points at x = radius^2 / 4.5 m (0.045 m for the 0.45 m modules).
      ASSERT_LT(p.x(), 0.046) << p.transpose();
    }
  }
  const std::string nav = test::readText(dir.path() / "riser" / "nav.csv");
  const std::string gt_nav = test::readText(dir.path() / "riser" / "ground_truth_poses.csv");
  EXPECT_NE(nav, gt_nav);
}

TEST(SimulationRun, CancellingKeepsTheFramesDoneAsAValidMission) {
  test::ScratchDir dir;
  CancelAfter progress(2);
  ThreadPool pool;
  const SimulationResult result = runSimulation(riserRequest(dir.path() / "m"), progress, pool);
  EXPECT_TRUE(result.cancelled);
  EXPECT_EQ(result.frames_written, 2u);
  const Mission mission = readMission(dir.path() / "m");
  EXPECT_EQ(mission.frames.size(), 2u);
  EXPECT_TRUE(checkFrames(mission).empty());
}

TEST(SimulationRun, EmptyWaterFramesHoldNoiseOnly) {
  test::ScratchDir dir;
  SilentProgress progress;
  SimulationRequest request = riserRequest(dir.path() / "empty");
  request.empty_water = true;
  request.noise.background_mean = 100.0;
  ThreadPool pool;
  runSimulation(request, progress, pool);
  const Mission mission = readMission(dir.path() / "empty");
  const Frame frame = loadFrame(mission, 0);
  // The riser at 4.3 m would be far above the background: the brightest pixel is noise.
  double max = 0.0;
  cv::minMaxLoc(frame.image, nullptr, &max);
  EXPECT_LT(max, 100.0 * 3.0 * 8.0);  // far Rayleigh tail at the brightest (near) background
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "empty" / "visible_points.ply"));
}

TEST(SceneIo, BrokenMeshFilesGetClearErrors) {
  test::ScratchDir dir;
  const auto expectError = [&](const std::string& name, const std::string& fragment) {
    try {
      loadSceneMesh(dir.path() / name);
      ADD_FAILURE() << name << " loaded";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  expectError("missing.stl", "not found");
  test::writeText(dir.path() / "empty.stl", "");
  expectError("empty.stl", "empty file");
  test::writeText(dir.path() / "garbage.ply", "ply\nformat ascii 1.0\nelement vertex 3\n");
  expectError("garbage.ply", "expected 'end_header'");
  test::writeText(dir.path() / "mesh.xyz", "1 2 3\n");
  expectError("mesh.xyz", "unknown mesh type");
  test::writeText(dir.path() / "solid.stl", "solid nothing\nendsolid nothing\n");
  expectError("solid.stl", "no triangles");
  // A valid mesh, truncated.
  const Scene riser = makeDemoScene("riser");
  writeScenePly(riser, dir.path() / "riser.ply");
  const std::string bytes = test::readText(dir.path() / "riser.ply");
  test::writeText(dir.path() / "cut.ply", bytes.substr(0, bytes.size() / 2));
  expectError("cut.ply", "truncated PLY");
  EXPECT_EQ(loadSceneMesh(dir.path() / "riser.ply").triangles.size(), riser.triangles.size());
}

}  // namespace
}  // namespace sonarcarve
