#include "model/elevation_profile.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "common/error.h"

namespace sonarcarve {
namespace {

ElevationProfile sampled(double theta_max_rad, int knots, double floor_db,
                         const std::function<double(double)>& power) {
  if (knots < 3) {
    throw Error("elevation profile", "knots", "expected at least 3 knots");
  }
  std::vector<double> db;
  for (int m = 0; m < knots; ++m) {
    const double p = power(theta_max_rad * m / (knots - 1));
    db.push_back(p > 0.0 ? std::max(floor_db, 10.0 * std::log10(p)) : floor_db);
  }
  return ElevationProfile(theta_max_rad, std::move(db));
}

}  // namespace

ElevationProfile::ElevationProfile(double theta_max_rad, std::vector<double> knots_db)
    : theta_max_rad_(theta_max_rad), knots_db_(std::move(knots_db)) {
  const bool finite =
      std::all_of(knots_db_.begin(), knots_db_.end(), [](double v) { return std::isfinite(v); });
  if (!(theta_max_rad > 0.0) || knots_db_.size() < 3 || !finite) {
    throw Error("elevation profile", "knots",
                "expected a positive extent and at least 3 finite knots");
  }
}

ElevationProfile ElevationProfile::sincSquared(double aperture_rad, double theta_max_rad, int knots,
                                               double floor_db) {
  const SincSquaredBeam beam(aperture_rad);
  return sampled(theta_max_rad, knots, floor_db, [&](double t) { return beam.power(t); });
}

ElevationProfile ElevationProfile::clipped(const BeamPattern& pattern, double theta_max_rad,
                                           int knots, double floor_db) {
  return sampled(theta_max_rad, knots, floor_db, [&](double t) { return pattern.weight(t); });
}

double ElevationProfile::knotAngle(int m) const {
  return theta_max_rad_ * m / (static_cast<int>(knots_db_.size()) - 1);
}

ProfileWeights ElevationProfile::weights(double theta_rad) const {
  const int n = static_cast<int>(knots_db_.size());
  const double t = std::min(std::abs(theta_rad), theta_max_rad_) / theta_max_rad_ * (n - 1);
  const int seg = std::min(static_cast<int>(t), n - 2);
  const double s = t - seg;
  const double s2 = s * s;
  const double s3 = s2 * s;
  // Catmull-Rom weights of the points seg-1, seg, seg+1, seg+2.
  const std::array<double, 4> w = {0.5 * (-s + 2.0 * s2 - s3), 0.5 * (2.0 - 5.0 * s2 + 3.0 * s3),
                                   0.5 * (s + 4.0 * s2 - 3.0 * s3), 0.5 * (-s2 + s3)};
  ProfileWeights out;
  int used = 0;
  const auto add = [&](int knot, double weight) {
    for (int u = 0; u < used; ++u) {
      if (out.knot[static_cast<std::size_t>(u)] == knot) {
        out.weight[static_cast<std::size_t>(u)] += weight;
        return;
      }
    }
    out.knot[static_cast<std::size_t>(used)] = knot;
    out.weight[static_cast<std::size_t>(used)] = weight;
    ++used;
  };
  for (int i = 0; i < 4; ++i) {
    const int point = seg - 1 + i;
    const double weight = w[static_cast<std::size_t>(i)];
    if (point < 0) {
      add(1, weight);  // mirrored about theta = 0
    } else if (point >= n) {
      add(n - 1, 2.0 * weight);  // continued linearly: 2 P[n-1] - P[n-2]
      add(n - 2, -weight);
    } else {
      add(point, weight);
    }
  }
  return out;
}

double ElevationProfile::levelDb(double theta_rad) const {
  const ProfileWeights w = weights(theta_rad);
  double db = 0.0;
  for (std::size_t i = 0; i < 4; ++i) {
    db += w.weight[i] * knots_db_[static_cast<std::size_t>(w.knot[i])];
  }
  return db;
}

double ElevationProfile::power(double theta_rad) const {
  return std::pow(10.0, levelDb(theta_rad) / 10.0);
}

double ElevationProfile::width(double level_db) const {
  const double axis = levelDb(0.0);
  constexpr int kSteps = 4000;
  double previous = 0.0;
  for (int i = 1; i <= kSteps; ++i) {
    const double theta = theta_max_rad_ * i / kSteps;
    const double below = axis - levelDb(theta);
    if (below >= -level_db) {
      // Between the last two steps, linearly in dB.
      const double before = axis - levelDb(previous);
      const double share = (-level_db - before) / std::max(below - before, 1e-12);
      return 2.0 * (previous + share * (theta - previous));
    }
    previous = theta;
  }
  return 2.0 * theta_max_rad_;
}

}  // namespace sonarcarve
