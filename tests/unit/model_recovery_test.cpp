// Parameters recovered through the forward model's gradient (model/forward_model.h) from frames
// it predicted: a beam profile from a mis-declared start, and a pose from an offset start.
#include <gtest/gtest.h>

#include <cmath>

#include "common/angles.h"
#include "model/forward_model.h"
#include "model/speckle_likelihood.h"
#include "support/model_scenes.h"
#include "support/small_bfgs.h"

namespace sonarcarve {
namespace {

constexpr double kVoxel = 0.02;

// A plane 2 m ahead turned 30 degrees about the sonar's y axis (its normal towards the sonar
// and up): each elevation meets it at its own range, r = 2 / cos(theta + 30 deg), so a frame
// of it reads the elevation profile; two vertical cylinders may stand in front of it.
BlockGrid tiltedPlaneScene(bool with_cylinders) {
  BlockGrid grid(kVoxel);
  const double beta = degToRad(30);
  const Eigen::Vector3d normal(-std::cos(beta), 0.0, -std::sin(beta));
  test::voxelise(
      grid, test::slab(-2.0 * normal, normal, 0.3),
      Eigen::AlignedBox3d(Eigen::Vector3d(1.3, -1.2, -5.5), Eigen::Vector3d(5.6, 1.2, 1.5)), 4.0,
      2.0, 0.8f);
  if (with_cylinders) {
    // At two ranges, so that a sideways shift and a yaw move them differently.
    for (const auto& [north, east] : {std::pair{1.4, -0.35}, std::pair{2.0, 0.3}}) {
      test::voxelise(grid, test::cylinder({north, east, 0.0}, Eigen::Vector3d::UnitZ(), 0.12),
                     Eigen::AlignedBox3d(Eigen::Vector3d(north - 0.25, east - 0.25, -1.5),
                                         Eigen::Vector3d(north + 0.25, east + 0.25, 1.5)),
                     4.0, 2.0, 0.6f);
    }
  }
  return grid;
}

SonarModel narrowSonar() {
  return SonarModel("recovery", RangeBins{1.0, 0.02, 350}, BearingTable::uniform(degToRad(16), 16),
                    degToRad(20));
}

ModelSettings coarseElevations() {
  ModelSettings settings;
  settings.elevation_step_rad = degToRad(0.5);
  return settings;
}

double gaussianDb(double theta_rad) {
  const double x = theta_rad / degToRad(10.0);
  return -3.0 * x * x;  // -3 dB at +-10 degrees
}

TEST(ModelRecovery, GaussianBeamProfileFromASincSquaredStart) {
  const SonarModel sonar = narrowSonar();
  ThreadPool pool(2);
  const ForwardModel model(sonar, coarseElevations(), pool);
  const BlockGrid grid = tiltedPlaneScene(false);
  const double theta_max = SincSquaredBeam(sonar.verticalAperture()).null(2);
  constexpr int kKnots = 7;
  std::vector<double> gaussian_knots;
  for (int m = 0; m < kKnots; ++m) {
    gaussian_knots.push_back(gaussianDb(theta_max * m / (kKnots - 1)));
  }
  FrameView truth{
      Eigen::Isometry3d::Identity(), ElevationProfile(theta_max, gaussian_knots), 1.0, {}};
  const cv::Mat clean = model.predict(grid, truth);
  double peak = 0.0;
  cv::minMaxLoc(clean, nullptr, &peak);
  // A faint background keeps the speckle likelihood's mean positive.
  truth.background.assign(static_cast<std::size_t>(sonar.rows()), 1e-5 * peak);
  const cv::Mat observed = model.predict(grid, truth);

  FrameView view = truth;
  view.profile = ElevationProfile::sincSquared(sonar.verticalAperture(), theta_max, kKnots);
  const test::Objective nll = [&](const Eigen::VectorXd& knots, Eigen::VectorXd& gradient) {
    view.profile.knotsDb().assign(knots.data(), knots.data() + knots.size());
    cv::Mat dloss;
    const double value = speckleNll(model.predict(grid, view), observed, &dloss);
    const ModelGradient g = model.gradient(grid, view, dloss);
    gradient = Eigen::Map<const Eigen::VectorXd>(g.knots_db.data(), kKnots);
    return value;
  };
  const std::vector<double>& start = view.profile.knotsDb();
  const Eigen::VectorXd x0 = Eigen::Map<const Eigen::VectorXd>(start.data(), kKnots);
  const test::BfgsResult fit =
      test::minimiseBfgs(nll, x0, Eigen::VectorXd::Constant(kKnots, 3.0), 40);
  view.profile.knotsDb().assign(fit.x.data(), fit.x.data() + kKnots);

  // The main lobe: the declared sinc^2's, to its first null.
  const double main_lobe = SincSquaredBeam(sonar.verticalAperture()).null(1);
  double worst_start = 0.0, worst_fit = 0.0;
  const ElevationProfile declared =
      ElevationProfile::sincSquared(sonar.verticalAperture(), theta_max, kKnots);
  for (double theta = 0.0; theta <= main_lobe; theta += degToRad(0.25)) {
    worst_start = std::max(worst_start, std::abs(declared.levelDb(theta) - gaussianDb(theta)));
    worst_fit = std::max(worst_fit, std::abs(view.profile.levelDb(theta) - gaussianDb(theta)));
  }
  std::printf(
      "beam profile over the main lobe (+-%.1f deg): worst error %.2f dB declared, %.3f dB "
      "fitted after %d BFGS steps\n",
      radToDeg(main_lobe), worst_start, worst_fit, fit.iterations);
  EXPECT_GT(worst_start, 3.0);  // the start is wrong
  EXPECT_LT(worst_fit, 1.0);
}

// The right Jacobian of SO(3) at omega: Exp(omega + d) = Exp(omega) Exp(J_r(omega) d) to first
// order.
Eigen::Matrix3d rightJacobian(const Eigen::Vector3d& omega) {
  const double angle = omega.norm();
  const Eigen::Matrix3d W{
      {0, -omega.z(), omega.y()}, {omega.z(), 0, -omega.x()}, {-omega.y(), omega.x(), 0}};
  if (angle < 1e-9) {
    return Eigen::Matrix3d::Identity() - 0.5 * W;
  }
  const double a2 = angle * angle;
  return Eigen::Matrix3d::Identity() - (1.0 - std::cos(angle)) / a2 * W +
         (angle - std::sin(angle)) / (a2 * angle) * W * W;
}

TEST(ModelRecovery, PoseOffsetOfThreeCentimetres) {
  const SonarModel sonar("pose", RangeBins{1.0, 0.02, 250}, BearingTable::uniform(degToRad(40), 48),
                         degToRad(20));
  ThreadPool pool(2);
  ModelSettings settings = coarseElevations();
  settings.elevation_step_rad = degToRad(1.0);
  const ForwardModel model(sonar, settings, pool);
  const BlockGrid grid = tiltedPlaneScene(true);
  const double theta_max = SincSquaredBeam(sonar.verticalAperture()).null(2);
  FrameView view{Eigen::Isometry3d::Identity(),
                 ElevationProfile::sincSquared(sonar.verticalAperture(), theta_max, 9),
                 1.0,
                 {}};
  const Eigen::Isometry3d truth = view.T_world_sonar;
  const cv::Mat observed = model.predict(grid, view);

  // The start: 3 cm off (1.8 cm forward, 1.5 cm to starboard, 1.8 cm up); the pose is
  // truth * [Exp(omega), v] with x = (v, omega), all six fitted.
  const Eigen::Vector3d offset(0.018, 0.015, -0.018);
  const auto poseOf = [&](const Eigen::VectorXd& x) {
    Eigen::Isometry3d step = Eigen::Isometry3d::Identity();
    step.translation() = x.head<3>();
    const Eigen::Vector3d omega = x.tail<3>();
    if (omega.norm() > 0.0) {
      step.linear() = Eigen::AngleAxisd(omega.norm(), omega.normalized()).toRotationMatrix();
    }
    return truth * step;
  };
  const test::Objective loss = [&](const Eigen::VectorXd& x, Eigen::VectorXd& gradient) {
    view.T_world_sonar = poseOf(x);
    cv::Mat dloss;
    const double value = squaredError(model.predict(grid, view), observed, &dloss);
    const Twist g = model.gradient(grid, view, dloss).twist;
    // Moving v by d moves the pose by (R(omega)^T d, 0) in its own frame; omega by d, by
    // (0, J_r(omega) d).
    const Eigen::Vector3d omega = x.tail<3>();
    const Eigen::Matrix3d R = truth.linear().transpose() * view.T_world_sonar.linear();
    gradient.resize(6);
    gradient.head<3>() = R * g.head<3>();
    gradient.tail<3>() = rightJacobian(omega).transpose() * g.tail<3>();
    return value;
  };
  Eigen::VectorXd x0 = Eigen::VectorXd::Zero(6);
  Eigen::VectorXd unused;
  x0.head<3>() = offset;
  Eigen::VectorXd scale(6);
  scale << 0.01, 0.01, 0.01, degToRad(0.5), degToRad(0.5), degToRad(0.5);
  // Stops when the loss is a millionth of the start's: the pose is then a few microns off.
  const test::BfgsResult fit = test::minimiseBfgs(loss, x0, scale, 40, 1e-6 * loss(x0, unused));
  const double translation_error = fit.x.head<3>().norm();
  const double rotation_error = fit.x.tail<3>().norm();
  std::printf("pose from a %.1f cm offset: %.2f mm and %.4f deg off after %d BFGS steps\n",
              100.0 * offset.norm(), 1000.0 * translation_error, radToDeg(rotation_error),
              fit.iterations);
  // A tenth of a voxel and of a range bin: the frames are noise-free and the model the same.
  EXPECT_LT(translation_error, 0.1 * kVoxel);
  EXPECT_LT(rotation_error, degToRad(0.05));
}

}  // namespace
}  // namespace sonarcarve
