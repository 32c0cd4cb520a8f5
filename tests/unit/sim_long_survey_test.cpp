// Long missions for the bench (issue 18): the seabed field holds seabed and objects anywhere,
// the same for the same seed; the long lawnmower and orbit have the asked geometry; the
// renderer holds only the field's tiles near the sonar; the simulator surveys a field.
#include <gtest/gtest.h>

#include <cmath>

#include "common/angles.h"
#include "common/error.h"
#include "sim/frame_renderer.h"
#include "sim/seabed_field.h"
#include "sim/simulation_run.h"
#include "sim/trajectory.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

// The renderer's window: the 10 m reach and a tile's margin on each side, 40.2 m, touches at
// most 6 x 6 tiles of 10 m, each of 800 seabed triangles and up to two objects (a sphere, the
// largest, has under 1,000).
constexpr std::size_t kMostWindowTriangles = 36 * (800 + 2 * 1000);

// Triangles of `scene` whose centre lies more than `height_m` above the field's seabed.
std::size_t trianglesAboveSeabed(const Scene& scene, const SeabedField& field, double height_m) {
  std::size_t count = 0;
  for (const auto& t : scene.triangles) {
    const Eigen::Vector3f c =
        (scene.vertices[t[0]] + scene.vertices[t[1]] + scene.vertices[t[2]]) / 3.0f;
    count += c.z() < field.seabedDown(c.x(), c.y()) - height_m ? 1 : 0;
  }
  return count;
}

TEST(SeabedField, FarAwayItStillHoldsSeabedAndObjects) {
  const SeabedField field(SeabedFieldSpec{});
  // 5 km north and 3 km east: an hour's survey does not get this far.
  const Scene far = field.area({Eigen::Vector2d(5000, 3000), Eigen::Vector2d(5049.9, 3049.9)});
  ASSERT_FALSE(far.triangles.empty());
  EXPECT_EQ(far.reflectivity.size(), far.triangles.size());
  const Eigen::Vector3d lo = far.boundsMin(), hi = far.boundsMax();
  EXPECT_NEAR(lo.x(), 5000.0, 1e-3);
  EXPECT_NEAR(hi.y(), 3050.0, 1e-3);
  EXPECT_GT(hi.z(), 20.0 - 0.5);  // the seabed, within its relief of 20 m
  EXPECT_LT(hi.z(), 20.0 + 0.5);
  // 25 tiles of up to two objects each: objects stand out of the seabed.
  EXPECT_GT(trianglesAboveSeabed(far, field, 0.2), 100u);
  EXPECT_GT(far.area(), 2500.0);  // at least the seabed's 50 m x 50 m
}

TEST(SeabedField, TheSameSeedGivesTheSameFieldAndTilesMeetWithoutSteps) {
  SeabedFieldSpec spec;
  const SeabedField a(spec), b(spec);
  const Scene tile_a = a.tile({12, -7});
  const Scene tile_b = b.tile({12, -7});
  ASSERT_EQ(tile_a.vertices.size(), tile_b.vertices.size());
  EXPECT_EQ(tile_a.vertices, tile_b.vertices);
  spec.seed = 2;
  EXPECT_NE(SeabedField(spec).tile({12, -7}).vertices, tile_a.vertices);
  // The seabed is one continuous surface: the relief is a function of the place alone.
  EXPECT_DOUBLE_EQ(a.seabedDown(130.0, -65.0), b.seabedDown(130.0, -65.0));
  EXPECT_LT(std::abs(a.seabedDown(130.0, -65.0) - a.seabedDown(130.01, -65.0)), 0.01);
  EXPECT_EQ(a.tileOf(-0.1, 10.0), Eigen::Vector2i(-1, 1));
  spec.tile_m = 1.0;
  EXPECT_THROW(SeabedField{spec}, Error);
}

TEST(LongSurvey, TheLawnmowerFliesLinesAtItsAltitudeWithTheSonarPitchedDown) {
  TrajectorySpec spec;
  spec.kind = "lawnmower";
  spec.step_m = 0.05;  // 0.5 m/s at 10 Hz
  spec.speed_mps = 0.5;
  spec.line_length_m = 50.0;
  spec.line_spacing_m = 5.0;
  spec.frames = 4000;
  const InspectionTarget target = SeabedField(SeabedFieldSpec{}).target();
  const Trajectory t = makeTrajectory(spec, target);
  ASSERT_EQ(t.poses.size(), 4000u);
  const std::size_t per_line = 1001;  // 50 m every 5 cm, both ends
  for (std::size_t i = 0; i < t.poses.size(); i += 97) {
    const Eigen::Isometry3d T = t.T_world_sonar(i);
    const std::size_t line = i / per_line;
    EXPECT_NEAR(T.translation().z(), 20.0 - 3.0, 1e-9) << i;  // 3 m above the mean seabed
    EXPECT_NEAR(T.translation().y(), -5.0 + 5.0 * static_cast<double>(line), 1e-9) << i;
    const Eigen::Vector3d boresight = T.linear() * Eigen::Vector3d::UnitX();
    EXPECT_NEAR(boresight.z(), std::sin(degToRad(30)), 1e-9);            // 30 degrees down
    EXPECT_NEAR(std::abs(boresight.x()), std::cos(degToRad(30)), 1e-9);  // along the line
    if (i % per_line != 0) {  // 5 cm and 0.1 s after the frame before, along the line
      EXPECT_NEAR((T.translation() - t.T_world_sonar(i - 1).translation()).norm(), 0.05, 1e-9);
      EXPECT_NEAR(t.poses[i].time_s - t.poses[i - 1].time_s, 0.1, 1e-9);
    }
  }
  // Each line is 50 m long; the second comes back south.
  EXPECT_NEAR((t.T_world_sonar(per_line - 1).translation() - t.T_world_sonar(0).translation())
                  .head<2>()
                  .norm(),
              50.0, 1e-6);
  EXPECT_LT(t.T_world_sonar(2 * per_line - 1).translation().x(),
            t.T_world_sonar(per_line).translation().x());
  spec.line_spacing_m = 0.0;
  EXPECT_THROW(makeTrajectory(spec, target), Error);
}

TEST(LongSurvey, TheOrbitGoesRoundAsManyLapsAsItsFramesMake) {
  TrajectorySpec spec;
  spec.kind = "orbit";
  spec.step_m = 0.05;
  spec.frames = 5000;
  const InspectionTarget target{Eigen::Vector3d(0, 0, 15), 9.5, 20.0, 20.0};
  const Trajectory t = makeTrajectory(spec, target);
  ASSERT_EQ(t.poses.size(), 5000u);
  double turned = 0.0;
  for (std::size_t i = 1; i < t.poses.size(); ++i) {
    const Eigen::Vector3d a = t.T_world_sonar(i - 1).translation();
    const Eigen::Vector3d b = t.T_world_sonar(i).translation();
    EXPECT_NEAR(b.head<2>().norm(), spec.standoff_m, 1e-6);
    turned += std::abs(std::remainder(std::atan2(b.y(), b.x()) - std::atan2(a.y(), a.x()),
                                      2.0 * 3.14159265358979));
  }
  // 4999 steps of 5 cm around a 4.5 m circle: 8.84 laps, descending over the span.
  EXPECT_NEAR(turned / (2.0 * 3.14159265358979), 4999 * 0.05 / (2.0 * 3.14159265358979 * 4.5),
              1e-3);
  EXPECT_NEAR(t.T_world_sonar(0).translation().z(), 9.5, 1e-9);
  EXPECT_NEAR(t.T_world_sonar(4999).translation().z(), 20.0 - 1.8, 1e-9);
  spec.frames = 0;
  spec.laps = 3.0;
  EXPECT_NEAR(static_cast<double>(makeTrajectory(spec, target).poses.size()),
              3.0 * 2.0 * 3.14159265358979 * 4.5 / 0.05, 1.0);
}

TEST(LongSurvey, TheRendererHoldsOnlyTheTilesNearTheSonar) {
  ThreadPool pool;
  ImagingSettings imaging = test::clippedBeam();
  imaging.elevation_step_rad = degToRad(1.0);  // a coarse, fast image: geometry is the point
  imaging.rays_per_beam = 1;
  const SonarModel sonar = paperSonar();
  const SeabedField field(SeabedFieldSpec{});
  FrameRenderer renderer(field, sonar, imaging, pool);
  TrajectorySpec spec;
  spec.kind = "lawnmower";
  spec.line_length_m = 2000.0;
  spec.step_m = 100.0;
  const Trajectory t = makeTrajectory(spec, field.target());
  ASSERT_GE(t.poses.size(), 20u);
  std::size_t lit_frames = 0;
  for (std::size_t i = 0; i < 20; ++i) {  // 2 km of seabed, frames 100 m apart
    const cv::Mat image = renderer.render(t.T_world_sonar(i));
    lit_frames += cv::countNonZero(image) > 1000 ? 1 : 0;
  }
  EXPECT_EQ(lit_frames, 20u);  // seabed under the sonar all along
  EXPECT_EQ(renderer.rebuilds(), 20u);
  // At most 6 x 6 tiles whatever the distance travelled.
  EXPECT_LT(renderer.mostTriangles(), kMostWindowTriangles);
  EXPECT_GT(renderer.tracedElevation(), 0.0);
}

TEST(LongSurvey, TheSimulatorSurveysAFieldAndWritesTheGroundTruthUnderTheTrack) {
  test::ScratchDir dir;
  TrajectorySpec trajectory;
  trajectory.kind = "lawnmower";
  trajectory.frames = 3;
  ImagingSettings imaging = test::clippedBeam();
  imaging.elevation_step_rad = degToRad(1.0);
  SimulationRequest request{Scene{},      "seabed-field",      paperSonar(),   trajectory,
                            imaging,      NoiseSpec::none(),   NavErrorSpec{}, false,
                            std::nullopt, dir.path() / "field"};
  SilentProgress progress;
  ThreadPool pool;
  const SimulationResult result = runSimulation(request, progress, pool, SeabedFieldSpec{});
  EXPECT_EQ(result.frames_written, 3u);
  EXPECT_GT(result.visible_points, 0u);
  EXPECT_GT(result.ground_truth_triangles, 0u);
  EXPECT_LE(result.most_triangles_traced, kMostWindowTriangles);
  const std::string settings = test::readText(dir.path() / "field" / "simulation.yaml");
  EXPECT_NE(settings.find("field:\n  seed: 1"), std::string::npos);
  EXPECT_NE(settings.find("frames: 3"), std::string::npos);
}

}  // namespace
}  // namespace sonarcarve
