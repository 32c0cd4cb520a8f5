#include "sonar/beam_pattern.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/error.h"

namespace sonarcarve {
namespace {

double sinc(double x) {
  return std::abs(x) < 1e-12 ? 1.0 : std::sin(x) / x;
}

// The x in (lo, hi) where the continuous `f` crosses `target`, f(lo) > target > f(hi): bisected.
template <typename F>
double crossing(F f, double target, double lo, double hi) {
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) > target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

void checkWidth(double width_rad, const char* what) {
  if (!(width_rad > 0.0) || !std::isfinite(width_rad)) {
    throw Error("sonar model", what, "expected a positive finite aperture");
  }
}

}  // namespace

double sincMinus3dBArgument() {
  // sin(x)/x falls monotonically from 1 to 0 on (0, pi): bisect once and cache.
  static const double x3db = crossing(sinc, std::pow(10.0, -0.3), 1e-9, std::numbers::pi);
  return x3db;
}

double sincSquaredMinus3dBArgument() {
  static const double x3db = crossing([](double x) { return sinc(x) * sinc(x); },
                                      std::pow(10.0, -0.3), 1e-9, std::numbers::pi);
  return x3db;
}

BeamPattern::BeamPattern(double aperture_rad) : aperture_rad_(aperture_rad) {
  checkWidth(aperture_rad, "vertical aperture");
  k_ = sincMinus3dBArgument() / (0.5 * aperture_rad);
}

double BeamPattern::weight(double elevation_rad) const {
  const double x = std::abs(k_ * elevation_rad);
  if (x < 1e-12) {
    return 1.0;
  }
  if (x >= std::numbers::pi) {
    return 0.0;
  }
  return std::sin(x) / x;
}

double BeamPattern::firstNull() const {
  return std::numbers::pi / k_;
}

SincSquaredBeam::SincSquaredBeam(double width_rad) : width_rad_(width_rad) {
  checkWidth(width_rad, "beam width");
  k_ = sincSquaredMinus3dBArgument() / (0.5 * width_rad);
}

double SincSquaredBeam::power(double angle_rad) const {
  const double s = amplitude(angle_rad);
  return s * s;
}

double SincSquaredBeam::amplitude(double angle_rad) const {
  return sinc(k_ * angle_rad);
}

double SincSquaredBeam::null(int n) const {
  return n * std::numbers::pi / k_;
}

double SincSquaredBeam::sideLobePeak(int n) const {
  // The peaks of sinc^2 beyond the main lobe solve tan x = x, i.e. sin x - x cos x = 0, once
  // in each (n pi, n pi + pi/2); that function's sign there starts as -(-1)^n n pi.
  const double sign = n % 2 == 0 ? 1.0 : -1.0;
  const double x =
      crossing([sign](double v) { return sign * (std::sin(v) - v * std::cos(v)); }, 0.0,
               n * std::numbers::pi + 0.5 * std::numbers::pi, n * std::numbers::pi);
  return x / k_;
}

double SincSquaredBeam::halfAngleAt(double level_db) const {
  if (!(level_db < 0.0)) {
    throw Error("beam pattern", "level", "expected a level below 0 dB");
  }
  const double x = crossing([](double v) { return sinc(v) * sinc(v); },
                            std::pow(10.0, level_db / 10.0), 1e-9, std::numbers::pi);
  return x / k_;
}

std::vector<double> meansOverBeams(const SincSquaredBeam& beam, double spacing_rad, int max_half,
                                   bool amplitude) {
  constexpr int kSamples = 16;  // across each beam's interval
  if (!(spacing_rad > 0.0) || max_half < 0) {
    throw Error("beam pattern", "beam spacing", "expected beams a positive angle apart");
  }
  const int half = static_cast<int>(std::min(beam.null(2) / spacing_rad, double(max_half)));
  std::vector<double> means;
  for (int d = -half; d <= half; ++d) {
    double sum = 0.0;
    for (int s = 0; s < kSamples; ++s) {
      const double angle = (d - 0.5 + (s + 0.5) / kSamples) * spacing_rad;
      sum += amplitude ? beam.amplitude(angle) : beam.power(angle);
    }
    means.push_back(sum / kSamples);
  }
  return means;
}

}  // namespace sonarcarve
