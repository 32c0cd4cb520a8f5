#include "fit/adam.h"

#include <algorithm>
#include <cmath>

namespace sonarcarve {
namespace {
constexpr double kBeta1 = 0.9;
constexpr double kBeta2 = 0.99;
constexpr double kRelativeEpsilon = 1e-2;
}  // namespace

void AdamState::step(std::vector<float>& x, const std::vector<double>& g,
                     const std::vector<std::uint8_t>& in_band, double learning_rate, double lo,
                     double hi) {
  update(x, g, &in_band, learning_rate, lo, hi);
}

void AdamState::step(std::vector<double>& x, const std::vector<double>& g, double learning_rate,
                     double lo, double hi) {
  update(x, g, nullptr, learning_rate, lo, hi);
}

template <typename T>
void AdamState::update(std::vector<T>& x, const std::vector<double>& g,
                       const std::vector<std::uint8_t>* in_band, double learning_rate, double lo,
                       double hi) {
  ++t_;
  const double c1 = 1.0 - std::pow(kBeta1, t_);
  const double c2 = 1.0 - std::pow(kBeta2, t_);
  double rms_sum = 0.0;
  std::size_t rms_count = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (in_band != nullptr && (*in_band)[i] == 0) {
      continue;
    }
    m_[i] = static_cast<float>(kBeta1 * m_[i] + (1.0 - kBeta1) * g[i]);
    v_[i] = static_cast<float>(kBeta2 * v_[i] + (1.0 - kBeta2) * g[i] * g[i]);
    if (v_[i] > 0.0f) {
      rms_sum += std::sqrt(v_[i] / c2);
      ++rms_count;
    }
  }
  if (rms_count == 0) {
    return;
  }
  const double epsilon = kRelativeEpsilon * rms_sum / static_cast<double>(rms_count);
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (in_band != nullptr && (*in_band)[i] == 0) {
      continue;
    }
    const double step = learning_rate * (m_[i] / c1) / (std::sqrt(v_[i] / c2) + epsilon);
    x[i] = static_cast<T>(std::clamp(static_cast<double>(x[i]) - step, lo, hi));
  }
}

}  // namespace sonarcarve
