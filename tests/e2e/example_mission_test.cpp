// End-to-end: the example mission a new user opens first (resources/example_mission), run
// with no options at all, maps the pipe it was made from. Its generator
// (make_example_mission.py) puts a vertical pipe 0.4 m in diameter 4.5 m north of the sonar's
// track, with Rayleigh speckle over every pixel and no empty-water recording.
#include <gtest/gtest.h>

#include <cmath>

#include "io/mesh/point_cloud_ply.h"
#include "support/cli_runner.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

constexpr double kPipeNorth = 4.5;
constexpr double kPipeRadius = 0.2;
// The evaluation's distance threshold (F@5cm): 2.5 voxels of the default 2 cm.
constexpr double kTolerance = 0.05;

TEST(ExampleMission, WithNoOptionsTheMapIsThePipe) {
  test::ScratchDir dir;
  const auto out = dir.path() / "out";
  const test::RunResult r = test::runCli("reconstruct " + test::quoted(test::exampleMission()) +
                                         " --out " + test::quoted(out) + " --mesh false");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("noise model learned from"), std::string::npos) << r.output;
  const PointCloud cloud = readPointCloudPly(out / "surface_points.ply");
  // The pipe's front half over the track's 1 m of depth is about 0.6 m x 1 m: hundreds of 2 cm
  // voxels; a map of speckle would hold tens of thousands, an empty one none.
  ASSERT_GT(cloud.positions.size(), 200u);
  ASSERT_LT(cloud.positions.size(), 5000u);
  std::size_t on_pipe = 0;
  for (const Eigen::Vector3f& p : cloud.positions) {
    const double off = std::abs(std::hypot(p.x() - kPipeNorth, p.y()) - kPipeRadius);
    on_pipe += off <= kTolerance ? 1 : 0;
  }
  EXPECT_GE(static_cast<double>(on_pipe), 0.95 * static_cast<double>(cloud.positions.size()))
      << on_pipe << " of " << cloud.positions.size() << " points within 5 cm of the pipe";
}

}  // namespace
}  // namespace sonarcarve
