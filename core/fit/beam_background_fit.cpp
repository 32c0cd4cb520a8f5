#include "fit/beam_background_fit.h"

#include <algorithm>
#include <cmath>

namespace sonarcarve {
namespace {

// Learning rates per step at the start: dB for the knots, natural log for the background.
constexpr double kKnotLearningRate = 0.3;
constexpr double kBackgroundLearningRate = 0.05;
// The fitted profile's knots stay within these levels (dB; the axis is near 0).
constexpr double kLowestKnotDb = -60.0;
constexpr double kHighestKnotDb = 6.0;
// Prior weights, in nats per pixel per dB^2. A profile 1 dB off its truth costs the frames'
// NLL about 1e-3 nats per pixel (a twentieth of the pixels return; each returning pixel's mean
// 23 % off costs 0.23^2 / 2): smoothness counts a tenth of that per dB of second difference,
// closeness to the declared profile a hundredth per dB of distance.
constexpr double kSmoothWeight = 1e-4;
constexpr double kDeclaredWeight = 1e-5;

// k[-1] = k[1] (the profile is mirrored about the axis); no second difference at the last knot
// (the profile continues linearly past it).
double secondDifference(const std::vector<double>& k, std::size_t m) {
  const double before = m == 0 ? k[1] : k[m - 1];
  return before - 2.0 * k[m] + k[m + 1];
}

// The profile's highest level (dB), on a fine grid of elevations.
double peakDb(const ElevationProfile& profile) {
  constexpr int kSteps = 400;
  double peak = -1e300;
  for (int i = 0; i <= kSteps; ++i) {
    peak = std::max(peak, profile.levelDb(profile.thetaMax() * i / kSteps));
  }
  return peak;
}

}  // namespace

BeamBackgroundFit::BeamBackgroundFit(const FrameView& declared, double background_floor,
                                     BeamBackgroundSettings settings)
    : declared_db_(declared.profile.knotsDb()),
      floor_(background_floor),
      settings_(settings),
      knot_steps_(declared.profile.knotsDb().size()),
      background_steps_(declared.background.size()) {
  for (const double b : declared.background) {
    log_background_.push_back(std::log(std::max(b, floor_)));
  }
}

double BeamBackgroundFit::priorPerPixel(const ElevationProfile& profile) const {
  const std::vector<double> c = correction(profile.knotsDb());
  double loss = 0.0;
  for (std::size_t m = 0; m + 1 < c.size(); ++m) {
    const double d2 = secondDifference(c, m);
    loss += kSmoothWeight * d2 * d2;
  }
  for (const double d : c) {
    loss += kDeclaredWeight * d * d;
  }
  return loss;
}

std::vector<double> BeamBackgroundFit::correction(const std::vector<double>& knots_db) const {
  std::vector<double> c(knots_db.size());
  for (std::size_t m = 0; m < c.size(); ++m) {
    c[m] = knots_db[m] - declared_db_[m];
  }
  return c;
}

std::vector<double> BeamBackgroundFit::priorGradient(const std::vector<double>& knots_db) const {
  const std::vector<double> c = correction(knots_db);
  std::vector<double> g(c.size(), 0.0);
  for (std::size_t m = 0; m + 1 < c.size(); ++m) {
    const double d = 2.0 * kSmoothWeight * secondDifference(c, m);
    g[m == 0 ? 1 : m - 1] += d;
    g[m] -= 2.0 * d;
    g[m + 1] += d;
  }
  for (std::size_t m = 0; m < c.size(); ++m) {
    g[m] += 2.0 * kDeclaredWeight * c[m];
  }
  return g;
}

void BeamBackgroundFit::step(FrameView& view, const ModelGradient& gradient, double pixels,
                             double share) {
  if (settings_.beam) {
    std::vector<double>& knots = view.profile.knotsDb();
    std::vector<double> g = priorGradient(knots);
    for (std::size_t m = 0; m < g.size(); ++m) {
      g[m] = gradient.knots_db[m] + pixels * g[m];
    }
    knot_steps_.step(knots, g, kKnotLearningRate * share, kLowestKnotDb, kHighestKnotDb);
    // The profile's shape only: its peak back to 0 dB, its level into the gain.
    const double peak = peakDb(view.profile);
    for (double& k : knots) {
      k -= peak;
    }
    view.gain *= std::pow(10.0, peak / 10.0);
  }
  if (settings_.background && !view.background.empty()) {
    std::vector<double> g(view.background.size());
    for (std::size_t k = 0; k < g.size(); ++k) {
      g[k] = gradient.background[k] * view.background[k];  // d / d log(B)
    }
    background_steps_.step(log_background_, g, kBackgroundLearningRate * share, std::log(floor_),
                           std::log(floor_) + 60.0);
    for (std::size_t k = 0; k < g.size(); ++k) {
      view.background[k] = std::exp(log_background_[k]);
    }
  }
}

}  // namespace sonarcarve
