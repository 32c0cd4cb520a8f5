// The elevation beam fitted with the map (fit/beam_background_fit.h): frames made through a
// beam narrower than the declared one give back the beam that made them, and the priors'
// gradient is the derivative of their loss.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "common/angles.h"
#include "fit/beam_background_fit.h"
#include "fit/map_fit.h"
#include "model/forward_model.h"
#include "support/model_scenes.h"

namespace sonarcarve {
namespace {

constexpr double kVoxel = 0.02;

SonarModel sonar() {
  return SonarModel("beam-fit", RangeBins{1.0, 0.02, 150}, BearingTable::uniform(degToRad(16), 16),
                    degToRad(20));
}

// A gaussian beam (a parabola in dB) of -3 dB full width `width_rad`, on the knots of `like`.
ElevationProfile gaussian(const ElevationProfile& like, double width_rad) {
  std::vector<double> knots;
  for (std::size_t m = 0; m < like.knotsDb().size(); ++m) {
    const double x = like.knotAngle(static_cast<int>(m)) / (0.5 * width_rad);
    knots.push_back(std::max(-60.0, -3.0 * x * x));
  }
  return ElevationProfile(like.thetaMax(), knots);
}

// A plane facing the sonar and tilted 45 deg up, so that range tells elevation: a ray 20 deg
// up meets it at 3.3 m, one 20 deg down at 1.6 m.
Eigen::AlignedBox3d box() {
  return {Eigen::Vector3d(1.0, -0.7, -1.9), Eigen::Vector3d(3.6, 0.7, 1.0)};
}

// The sonar pitched from 16 deg down to 16 deg up: every part of the plane is seen across the
// whole main lobe, so that its reflectance cannot stand in for the beam.
std::vector<MapFitFrame> views() {
  std::vector<MapFitFrame> frames;
  std::size_t index = 0;
  for (double pitch_deg = -16.0; pitch_deg <= 16.0; pitch_deg += 4.0) {
    MapFitFrame frame;
    frame.index = index++;
    frame.T_world_sonar =
        Eigen::Isometry3d(Eigen::AngleAxisd(degToRad(pitch_deg), Eigen::Vector3d::UnitY()));
    frames.push_back(frame);
  }
  return frames;
}

TEST(BeamFit, FramesThroughANarrowerBeamGiveItBack) {
  const SonarModel s = sonar();
  ThreadPool pool(2);
  MapFitParams params;
  params.enabled = true;
  params.passes = 24;
  params.frames_per_step = 1;
  params.elevation_step_rad = degToRad(0.5);
  params.background = false;
  ModelSettings settings;
  settings.elevation_step_rad = params.elevation_step_rad;
  settings.samples_per_bin = params.samples_per_bin;
  const ForwardModel model(s, settings, pool);

  FitGrid truth{BlockGrid(kVoxel), {}};
  const Eigen::Vector3d normal = Eigen::Vector3d(-1.0, 0.0, -1.0).normalized();
  test::voxelise(truth.grid, test::slab({2.0, 0.0, 0.0}, normal, 0.2), box(), 4.0, 2.0, 0.7f);
  const ElevationProfile declared = declaredProfile(s);
  const ElevationProfile true_beam = gaussian(declared, degToRad(14.0));
  const std::vector<MapFitFrame> frames = views();
  FrameView view{Eigen::Isometry3d::Identity(), true_beam, 3.0, {}};
  std::vector<cv::Mat> observed;
  for (const MapFitFrame& frame : frames) {
    view.T_world_sonar = frame.T_world_sonar;
    cv::Mat image;
    model.predict(truth.grid, view).convertTo(image, CV_32F);
    observed.push_back(image);
  }
  ASSERT_GT(cv::sum(observed[4])[0], 10.0);

  // The map starts as it is (its reflectance 1, not 0.7): only the beam is wrong.
  truth.in_band.assign(truth.grid.voxelCount(), 1);
  std::fill(truth.grid.reflectance().begin(), truth.grid.reflectance().end(), 1.0f);
  SilentProgress progress;
  const MapFitSummary summary =
      MapFit(s, params, pool)
          .run(
              truth, frames, [&](std::size_t i) { return observed[i]; }, {}, progress);
  ASSERT_TRUE(summary.fitted_profile.has_value());
  // Over the true main lobe (to -10 dB, +-13 deg), within 1 dB; the declared is 4 dB off there.
  double worst_declared = 0.0;
  double worst_fitted = 0.0;
  for (double deg = -12.5; deg <= 12.5; deg += 0.5) {
    const double theta = degToRad(deg);
    worst_fitted = std::max(
        worst_fitted, std::abs(summary.fitted_profile->levelDb(theta) - true_beam.levelDb(theta)));
    EXPECT_NEAR(summary.fitted_profile->levelDb(theta), true_beam.levelDb(theta), 1.0) << deg;
    worst_declared =
        std::max(worst_declared, std::abs(declared.levelDb(theta) - true_beam.levelDb(theta)));
  }
  EXPECT_GT(worst_declared, 3.0);
  std::printf("main lobe: fitted within %.2f dB of the true beam, declared %.2f dB off\n",
              worst_fitted, worst_declared);
  EXPECT_NEAR(summary.fitted_profile->width(-3.0), degToRad(14.0), degToRad(1.0));
  EXPECT_LT(summary.after.nll_per_pixel, summary.before.nll_per_pixel);
}

TEST(BeamFit, PriorGradientIsTheDerivativeOfThePrior) {
  const ElevationProfile declared = declaredProfile(sonar());
  FrameView view{Eigen::Isometry3d::Identity(), declared, 1.0, {}};
  BeamBackgroundFit fit(view, 1e-3, {true, false});
  std::mt19937 rng(3);
  std::normal_distribution<double> jitter(0.0, 3.0);
  ElevationProfile moved = declared;
  for (double& k : moved.knotsDb()) {
    k += jitter(rng);
  }
  // Steps with no data gradient move the knots down the prior's gradient.
  const double before = fit.priorPerPixel(moved);
  FrameView stepped{Eigen::Isometry3d::Identity(), moved, 1.0, {}};
  ModelGradient none(0, moved.knotsDb().size(), 0);
  for (int i = 0; i < 20; ++i) {
    fit.step(stepped, none, 1.0, 1.0);
  }
  EXPECT_LT(fit.priorPerPixel(stepped.profile), 0.8 * before);
}

}  // namespace
}  // namespace sonarcarve
