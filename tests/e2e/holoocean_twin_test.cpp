// HoloOcean / NeuSIS datasets read in place (issue 43): the simulated riser, noise-free, written
// in the NeuSIS layout by the test writer (support/pickle_writer.h: each frame's image as
// float32 with HoloOcean's column order, its sonar's world pose as HoloOcean's 4 x 4 float32
// PoseSensor, Config.json with the sonar's window), is recognised by its content and
// reconstructs to the F-score of the mission folder it came from.
//
// Tolerance: the images are the same numbers (power of 16-bit counts: whole numbers below 2^24,
// exact in float32). The poses lose float32's rounding: 2^-24 of 10 m is 0.6 um of position and
// 1e-7 rad of attitude (1e-6 m at the 10 m range), a thousandth of a 2 cm voxel; a voxel whose
// centre lies within that of a pixel's edge may be carved once more or less, a few voxels of
// the tens of thousands of the surface. The twin is read with the mission's elevation beam
// (--beam-pattern sinc; HoloOcean's own is clipped). The F-scores agree to 0.005.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "io/mission/mission.h"
#include "support/cli_runner.h"
#include "support/pickle_writer.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

using test::quoted;
using test::runCli;

constexpr double kSameFscore = 0.005;

class HoloOceanTwin : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::ScratchDir;
    const auto sim = runCli("simulate --scene riser --noise none --max-frames 20 --out " +
                            quoted(path("mission")));
    ASSERT_EQ(sim.exit_code, 0) << sim.output;
    test::writeNeusisDataset(readMission(path("mission")), path("neusis"), 4);
    const auto folder =
        runCli("reconstruct " + quoted(path("mission")) + " --out " + quoted(path("mission.out")));
    ASSERT_EQ(folder.exit_code, 0) << folder.output;
    const auto twin = runCli("reconstruct " + quoted(path("neusis")) +
                             " --beam-pattern sinc --out " + quoted(path("neusis.out")));
    ASSERT_EQ(twin.exit_code, 0) << twin.output;
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }
  static std::filesystem::path path(const std::string& name) { return dir_->path() / name; }

  static double fscore(const std::string& run) {
    return test::evaluatedFscore(path("mission") / "ground_truth.ply",
                                 path("mission") / "visible_points.ply",
                                 path(run) / "surface_points.ply");
  }

  static test::ScratchDir* dir_;
};

test::ScratchDir* HoloOceanTwin::dir_ = nullptr;

TEST_F(HoloOceanTwin, ReconstructsToTheFscoreOfItsMissionFolder) {
  const double folder = fscore("mission.out");
  const double twin = fscore("neusis.out");
  RecordProperty("fscore_folder", std::to_string(folder));
  RecordProperty("fscore_neusis", std::to_string(twin));
  std::cout << "F-score: mission folder " << folder << ", NeuSIS twin " << twin << "\n";
  EXPECT_GT(folder, 0.7) << "a noise-free riser, 20 of its frames";
  EXPECT_NEAR(twin, folder, kSameFscore);
}

TEST_F(HoloOceanTwin, InfoNamesTheDatasetItsFramesAndConventions) {
  const auto info = runCli("info " + quoted(path("neusis")));
  ASSERT_EQ(info.exit_code, 0) << info.output;
  EXPECT_NE(info.output.find("HoloOcean / NeuSIS dataset: 20 of 20 frames, images 500 x 650"),
            std::string::npos)
      << info.output;
  EXPECT_NE(info.output.find("x forward, y left, z up taken as north, west, up"), std::string::npos)
      << info.output;
}

TEST_F(HoloOceanTwin, ImportWritesAMissionFolderOfTheSameFrames) {
  const auto import =
      runCli("import " + quoted(path("neusis")) + " --out " + quoted(path("imported")));
  ASSERT_EQ(import.exit_code, 0) << import.output;
  const Mission imported = readMission(path("imported"));
  const Mission original = readMission(path("mission"));
  ASSERT_EQ(imported.frames.size(), original.frames.size());
  for (std::size_t k : {std::size_t{0}, original.frames.size() - 1}) {
    const cv::Mat a = loadFrame(original, k).image;
    const cv::Mat b = loadFrame(imported, k).image;
    EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0) << "frame " << k;
  }
}

}  // namespace
}  // namespace sonarcarve
