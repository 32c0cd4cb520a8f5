// The forward model's reverse pass (model/forward_model.h) against central finite differences
// of the predicted frame, on a small random grid, for every kind of parameter.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numeric>
#include <random>

#include "common/angles.h"
#include "model/forward_model.h"
#include "model/speckle_likelihood.h"

namespace sonarcarve {
namespace {

constexpr double kVoxel = 0.05;

SonarModel smallSonar() {
  return SonarModel("fd", RangeBins{2.0, 0.02, 100}, BearingTable::uniform(degToRad(20), 12),
                    degToRad(20));
}

// A rough, noisy surface near x = 3 m across the fan, in random blocks of random reflectance.
// The outer shell of blocks stays empty, so that the grid's edge (where absent voxels begin) is
// not where the model changes.
BlockGrid randomGrid(std::mt19937& rng) {
  BlockGrid grid(kVoxel);
  std::uniform_real_distribution<double> noise(-1.0, 1.0);
  std::uniform_real_distribution<double> reflectance(0.3, 1.0);
  for (int bx = 5; bx <= 8; ++bx) {
    for (int by = -3; by <= 2; ++by) {
      for (int bz = -3; bz <= 2; ++bz) {
        grid.addBlock({bx, by, bz});
      }
    }
  }
  for (std::size_t i = 0; i < grid.voxelCount(); ++i) {
    const Eigen::Vector3d c = grid.voxelCentre(grid.voxelAt(static_cast<std::int64_t>(i)));
    const bool edge = c.x() < 2.1 || c.x() > 3.4 || std::abs(c.y()) > 0.9 || std::abs(c.z()) > 0.9;
    const double surface = 3.0 + 0.1 * std::sin(4.0 * c.y()) + 0.05 * c.z();
    grid.logits()[i] =
        edge ? grid.emptyLogit()
             : static_cast<float>(std::clamp(20.0 * (c.x() - surface), -6.0, 6.0) + noise(rng));
    grid.reflectance()[i] = static_cast<float>(reflectance(rng));
  }
  return grid;
}

struct Fixture {
  std::mt19937 rng{41};
  SonarModel sonar = smallSonar();
  ThreadPool pool{2};
  ModelSettings settings = [] {
    ModelSettings s;
    s.elevation_step_rad = degToRad(1.0);
    s.min_alpha = 0.0;  // every sample kept: the model is smooth in every parameter
    s.min_transmittance = 0.0;
    return s;
  }();
  ForwardModel model{sonar, settings, pool};
  BlockGrid grid = randomGrid(rng);
  FrameView view{[] {
                   Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
                   T.translate(Eigen::Vector3d(0.02, -0.03, 0.01));
                   T.rotate(Eigen::AngleAxisd(degToRad(2), Eigen::Vector3d::UnitZ()));
                   T.rotate(Eigen::AngleAxisd(degToRad(-3), Eigen::Vector3d::UnitY()));
                   return T;
                 }(),
                 ElevationProfile::sincSquared(degToRad(20), degToRad(20), 6), 1.7,
                 std::vector<double>(100, 0.0)};
  cv::Mat weights = [this] {
    cv::Mat w(sonar.rows(), sonar.cols(), CV_64F);
    cv::randu(w, -1.0, 1.0);
    return w;
  }();

  // The loss sum W * I, linear in the frame: d loss / d I = W.
  double loss(const BlockGrid& g, const FrameView& v) const {
    return model.predict(g, v).dot(weights);
  }
  template <typename Perturb>
  double centralDifference(double h, Perturb perturb) const {
    BlockGrid g = grid;
    FrameView v = view;
    perturb(g, v, h);
    const double up = loss(g, v);
    g = grid;
    v = view;
    perturb(g, v, -h);
    return (up - loss(g, v)) / (2.0 * h);
  }
};

// Central differences err by h^2 f''' / 6 (truncation) and eps |L| / h (rounding). The model is
// smooth in the logits, the knots and the reflectance at the scale of a unit (sigmoid's third
// derivative is at most 1/8; a knot moves the power by ln(10)/10 per dB): with h = 2^-10
// (exact on the float parameters) the truncation is ~1e-7 relative and the rounding of the
// double sums, 1e-16 |L| / 1e-3 times the square root of the terms summed, far below. In the pose
// the model is continuous with kinks where a sample crosses a plane of voxel centres (trilinear
// weights). A step of 1e-7 m or rad moves the ~10^5 samples of the test's frame (rotations
// move the far ones most) across such a plane a few times in ten: of three steps from 1e-8 to
// 1e-7 the closest difference is taken, which a wrong derivative cannot match at any step. Their
// rounding is at most 1e-16 |L| / 1e-8 = 1e-8 |L|. Relative 1e-4 (plus an absolute floor of
// 1e-12 |L| / h, a thousand times the rounding, for derivatives that vanish) covers both.
void expectMatches(double analytic, double fd, double loss_scale, double h, const char* what,
                   double& worst) {
  const double floor = 1e-12 * loss_scale / h;
  const double error = std::abs(analytic - fd);
  EXPECT_LE(error, 1e-4 * std::abs(fd) + floor)
      << what << ": analytic " << analytic << " fd " << fd;
  if (std::abs(fd) > 100.0 * floor) {
    worst = std::max(worst, error / std::abs(fd));
  }
}

TEST(ModelGradient, EveryDerivativeMatchesCentralDifferences) {
  Fixture f;
  std::uniform_real_distribution<double> bg(0.1, 0.5);
  for (double& b : f.view.background) {
    b = bg(f.rng);
  }
  const cv::Mat frame = f.model.predict(f.grid, f.view);
  ASSERT_GT(cv::sum(frame)[0] - cv::sum(f.view.background)[0] * f.sonar.cols(), 1.0);
  const double scale = cv::sum(cv::abs(frame.mul(f.weights)))[0];
  const ModelGradient grad = f.model.gradient(f.grid, f.view, f.weights);

  // The voxels with the largest logit and reflectance derivatives, and some random ones.
  std::vector<std::size_t> voxels;
  for (const auto* values : {&grad.logits, &grad.reflectance}) {
    std::vector<std::size_t> order(values->size());
    std::iota(order.begin(), order.end(), 0);
    std::partial_sort(order.begin(), order.begin() + 8, order.end(), [&](auto a, auto b) {
      return std::abs((*values)[a]) > std::abs((*values)[b]);
    });
    voxels.insert(voxels.end(), order.begin(), order.begin() + 8);
  }
  std::uniform_int_distribution<std::size_t> any(0, f.grid.voxelCount() - 1);
  for (int i = 0; i < 8; ++i) {
    voxels.push_back(any(f.rng));
  }
  double worst_logit = 0.0, worst_rho = 0.0, worst_knot = 0.0, worst_pose = 0.0, worst_other = 0.0;
  const double h = 1.0 / 1024.0;  // exact steps on float parameters below 8
  for (const std::size_t v : voxels) {
    expectMatches(grad.logits[v],
                  f.centralDifference(h, [v](BlockGrid& g, FrameView&,
                                             double d) { g.logits()[v] += static_cast<float>(d); }),
                  scale, h, "logit", worst_logit);
    expectMatches(
        grad.reflectance[v],
        f.centralDifference(h, [v](BlockGrid& g, FrameView&,
                                   double d) { g.reflectance()[v] += static_cast<float>(d); }),
        scale, h, "reflectance", worst_rho);
  }
  for (std::size_t m = 0; m < grad.knots_db.size(); ++m) {
    expectMatches(grad.knots_db[m],
                  f.centralDifference(
                      h, [m](BlockGrid&, FrameView& v, double d) { v.profile.knotsDb()[m] += d; }),
                  scale, h, "knot", worst_knot);
  }
  expectMatches(grad.gain,
                f.centralDifference(h, [](BlockGrid&, FrameView& v, double d) { v.gain += d; }),
                scale, h, "gain", worst_other);
  for (std::size_t k : {0UL, 37UL, 99UL}) {
    expectMatches(
        grad.background[k],
        f.centralDifference(h, [k](BlockGrid&, FrameView& v, double d) { v.background[k] += d; }),
        scale, h, "background", worst_other);
  }
  // In the pose: of three steps, the one whose difference is closest (the others may straddle a
  // kink, see above).
  for (int i = 0; i < 6; ++i) {
    double closest = std::numeric_limits<double>::infinity();
    for (const double hp : {1e-8, 3e-8, 1e-7}) {
      const double fd = f.centralDifference(hp, [i](BlockGrid&, FrameView& v, double d) {
        Twist xi = Twist::Zero();
        xi[i] = d;
        v.T_world_sonar = applyTwist(v.T_world_sonar, xi);
      });
      if (std::abs(fd - grad.twist[i]) < std::abs(closest - grad.twist[i])) {
        closest = fd;
      }
    }
    expectMatches(grad.twist[i], closest, scale, 1e-7, "pose", worst_pose);
  }
  std::printf(
      "worst relative error: logit %.2e reflectance %.2e knots %.2e pose %.2e gain and "
      "background %.2e\n",
      worst_logit, worst_rho, worst_knot, worst_pose, worst_other);
}

// One march shared by the prediction and the gradient (a FrameTrace) gives what two give, for
// every beam and for a step's subset of beams.
TEST(ModelGradient, TracedFrameGivesThePredictionAndGradientOfTwoMarches) {
  Fixture f;
  for (const int stride : {1, 3}) {
    ModelSettings settings = f.settings;
    settings.beam_stride = stride;
    settings.beam_offset = stride - 1;
    const ForwardModel model(f.sonar, settings, f.pool);
    FrameTrace trace;
    model.trace(f.grid, f.view, trace);
    EXPECT_GT(trace.samples(), 1000u);
    EXPECT_EQ(cv::norm(model.predict(trace, f.view), model.predict(f.grid, f.view), cv::NORM_INF),
              0.0);
    const ModelGradient traced = model.gradient(trace, f.grid, f.view, f.weights);
    const ModelGradient marched = model.gradient(f.grid, f.view, f.weights);
    // Sums in another order per thread: equal to rounding.
    const auto close = [](const std::vector<double>& a, const std::vector<double>& b) {
      double worst = 0.0;
      double scale = 0.0;
      for (std::size_t i = 0; i < a.size(); ++i) {
        worst = std::max(worst, std::abs(a[i] - b[i]));
        scale = std::max(scale, std::abs(b[i]));
      }
      return worst <= 1e-12 * scale;
    };
    EXPECT_TRUE(close(traced.logits, marched.logits)) << stride;
    EXPECT_TRUE(close(traced.reflectance, marched.reflectance)) << stride;
    EXPECT_TRUE(close(traced.knots_db, marched.knots_db)) << stride;
    EXPECT_LE((traced.twist - marched.twist).norm(), 1e-12 * marched.twist.norm()) << stride;
  }
}

TEST(ModelGradient, SpeckleNllGradientMatchesCentralDifferences) {
  cv::Mat predicted(4, 5, CV_64F), observed(4, 5, CV_32F);
  cv::randu(predicted, 0.5, 3.0);
  cv::randu(observed, 0.0, 4.0);
  cv::Mat gradient;
  const double nll = speckleNll(predicted, observed, &gradient);
  EXPECT_TRUE(std::isfinite(nll));
  const double h = 1e-5;
  for (int r = 0; r < predicted.rows; ++r) {
    for (int c = 0; c < predicted.cols; ++c) {
      cv::Mat up = predicted.clone(), down = predicted.clone();
      up.at<double>(r, c) += h;
      down.at<double>(r, c) -= h;
      const double fd = (speckleNll(up, observed) - speckleNll(down, observed)) / (2 * h);
      EXPECT_NEAR(gradient.at<double>(r, c), fd, 1e-6 * (1.0 + std::abs(fd)));
    }
  }
  // Minimal where the prediction equals the observation.
  cv::Mat matched;
  observed.convertTo(matched, CV_64F);
  matched += 0.1;
  cv::Mat zero;
  speckleNll(matched, matched, &zero);
  EXPECT_LT(cv::norm(zero, cv::NORM_INF), 1e-12);
}

}  // namespace
}  // namespace sonarcarve
