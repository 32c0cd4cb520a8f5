// The simulator against analytic cases of the imaging model (sim/sonar_simulator.h).
#include <gtest/gtest.h>

#include <vtkPlaneSource.h>
#include <cmath>

#include "common/angles.h"
#include "sim/demo_scenes.h"
#include "sim/ray_caster.h"
#include "sim/sonar_simulator.h"
#include "support/sim_scenes.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

using test::plate;
using test::sphereScene;

// A small sonar for fast tests: 2 cm bins to 10 m, 41 beams over 40 deg, 20 deg aperture.
SonarModel testSonar() {
  return SonarModel("test", RangeBins{0.0, 0.02, 500}, BearingTable::uniform(degToRad(40), 41),
                    degToRad(20));
}

// Sonar at the origin looking north (world = sonar frame).
cv::Mat render(const Scene& scene, const SonarModel& sonar,
               ImagingSettings settings = test::clippedBeam()) {
  ThreadPool pool;
  const RayCaster caster(scene);
  const SonarSimulator sim(caster, sonar, settings, pool);
  return sim.render(Eigen::Isometry3d::Identity());
}

double columnSum(const cv::Mat& image, int col) {
  return cv::sum(image.col(col))[0];
}

TEST(SimImageFormation, WallFacingTheSonarLightsTheBinOfItsDistance) {
  const SonarModel sonar = testSonar();
  for (double d : {2.0, 4.5, 7.31}) {
    // A 12 m x 12 m wall facing the sonar at north = d.
    const Scene wall = plate({d, 0, 0}, {-1, 0, 0}, 12.0, 0.8f);
    const cv::Mat image = render(wall, sonar);
    for (int col = 0; col < sonar.cols(); ++col) {
      const double bearing = sonar.bearings().centre(col);
      double peak = 0.0;
      cv::Point at;
      cv::minMaxLoc(image.col(col), nullptr, &peak, nullptr, &at);
      const int expected = *sonar.range().binOf(d / std::cos(bearing));
      EXPECT_NEAR(at.y, expected, 1) << "d " << d << " beam " << col;
      // Nothing nearer than the wall: the nearest lit bin is the wall's.
      for (int row = 0; row < expected - 1; ++row) {
        ASSERT_EQ(image.at<float>(row, col), 0.0f) << "d " << d << " row " << row;
      }
    }
  }
}

TEST(SimImageFormation, TiltedPlaneFollowsTheCosineLaw) {
  const SonarModel sonar = testSonar();
  const int centre = sonar.cols() / 2;
  const double facing = columnSum(render(plate({5, 0, 0}, {-1, 0, 0}, 12.0, 0.8f), sonar), centre);
  ASSERT_GT(facing, 0.0);
  for (double tilt_deg : {20.0, 40.0, 60.0}) {
    // Turned about the vertical through the boresight's hit point: the centre beam's rays hit
    // at the same ranges, only the incidence changes.
    const double t = degToRad(tilt_deg);
    const Scene tilted = plate({5, 0, 0}, {-std::cos(t), std::sin(t), 0}, 12.0, 0.8f);
    const double ratio = columnSum(render(tilted, sonar), centre) / facing;
    EXPECT_NEAR(ratio, std::cos(t), 0.01 * std::cos(t)) << tilt_deg;
  }
}

TEST(SimImageFormation, ReturnsFollowTheBeamPatternAcrossTheAperture) {
  const SonarModel sonar = testSonar();
  ImagingSettings fine = test::clippedBeam();
  fine.elevation_step_rad = degToRad(0.02);
  const double range = 5.0;
  // A 10 cm plate facing the sonar at elevation theta; its energy relative to theta = 0
  // follows b(theta), and it is not seen at all outside the aperture.
  const auto energyAt = [&](double theta_deg) {
    const double t = degToRad(theta_deg);
    const Eigen::Vector3d centre = pointFromPolar({range, 0.0, t});
    return cv::sum(render(plate(centre, -centre.normalized(), 0.1, 0.8f), sonar, fine))[0];
  };
  const double on_axis = energyAt(0.0);
  ASSERT_GT(on_axis, 0.0);
  for (double theta_deg : {-9.3, -6.0, 3.0, 8.0, 9.3}) {
    const double expected = sonar.beamPattern().weight(degToRad(theta_deg));
    EXPECT_NEAR(energyAt(theta_deg) / on_axis, expected, 0.03) << theta_deg;
  }
  EXPECT_NEAR(10 * std::log10(energyAt(9.3) / on_axis), -2.7, 0.25);  // just inside -3 dB
  EXPECT_EQ(energyAt(11.0), 0.0);
  EXPECT_EQ(energyAt(-11.0), 0.0);
}

TEST(SimImageFormation, StarboardObjectAppearsAtPositiveBearing) {
  const SonarModel sonar = testSonar();
  const Eigen::Vector3d target(5.0, 1.2, 0.0);  // east of a north-looking sonar: starboard
  const cv::Mat image = render(sphereScene({{target, 0.1}}), sonar);
  cv::Point peak;
  cv::minMaxLoc(image, nullptr, nullptr, nullptr, &peak);
  const double bearing = sonar.bearings().centre(peak.x);
  EXPECT_GT(bearing, 0.0);
  EXPECT_NEAR(bearing, std::atan2(1.2, 5.0), degToRad(40.0 / 41.0));
  EXPECT_NEAR(sonar.range().centre(peak.y), target.norm() - 0.1, 0.04);
}

TEST(SimImageFormation, SmallSphereBehindALargeOneIsShadowed) {
  const SonarModel sonar = testSonar();
  const Eigen::Vector3d front(3.0, 0, 0), behind(6.0, 0, 0);
  const auto energyNear = [&](const cv::Mat& image, double r) {
    const int row = *sonar.range().binOf(r);
    return cv::sum(image.rowRange(row - 3, row + 6))[0];
  };
  const cv::Mat alone = render(sphereScene({{behind, 0.15}}), sonar);
  const cv::Mat shadowed = render(sphereScene({{front, 0.6}, {behind, 0.15}}), sonar);
  EXPECT_GT(energyNear(alone, 5.85), 0.0);
  EXPECT_EQ(energyNear(shadowed, 5.85), 0.0);
  EXPECT_GT(energyNear(shadowed, 2.4), 0.0);  // the front sphere itself
}

TEST(SimImageFormation, GrazingSeabedGivesNoStriping) {
  // A flat seabed 1.5 m below a sonar pitched down 10 degrees: range grows fast with
  // elevation, and each bin in the lit span must get a share, with no empty bins between.
  const SonarModel sonar = testSonar();
  const RayCaster caster(plate({5, 0, 1.5}, {0, 0, -1}, 30.0, 0.5f));
  ThreadPool pool;
  const SonarSimulator sim(caster, sonar, test::clippedBeam(), pool);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(degToRad(-10), Eigen::Vector3d::UnitY()).toRotationMatrix();
  const cv::Mat image = sim.render(T);
  const int col = sonar.cols() / 2;
  // Lit span of the centre beam: from 1.5 / sin(20 deg) to 1.5 / sin(0 deg) -> to max range.
  const int first = *sonar.range().binOf(1.5 / std::sin(degToRad(20))) + 2;
  // The last bins are cut by the range window: rays past 10 m return nothing.
  const int last = sonar.rows() - 5;
  double previous = image.at<float>(first, col);
  for (int row = first; row <= last; ++row) {
    const double v = image.at<float>(row, col);
    ASSERT_GT(v, 0.0) << "empty bin " << row;
    // Smooth: neighbouring bins differ by less than a third (striping would alternate).
    ASSERT_LT(std::abs(v - previous), 0.34 * std::max(v, previous)) << "bin " << row;
    previous = v;
  }
}

TEST(SimImageFormation, RiserDemoShowsTheRiserAtItsStandoff) {
  const Scene riser = makeDemoScene("riser");
  const SonarModel sonar = testSonar();
  const RayCaster caster(riser);
  ThreadPool pool;
  const SonarSimulator sim(caster, sonar, test::clippedBeam(), pool);
  // Sonar level at 17 m depth, 4.5 m south of the riser axis, looking north.
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(-4.5, 0, 17.0);
  const cv::Mat image = sim.render(T);
  cv::Point peak;
  cv::minMaxLoc(image.col(sonar.cols() / 2), nullptr, nullptr, nullptr, &peak);
  EXPECT_NEAR(sonar.range().centre(peak.y), 4.5 - 0.2, 0.03);  // pipe radius 0.2 m
}

}  // namespace
}  // namespace sonarcarve
