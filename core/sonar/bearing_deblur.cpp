#include "sonar/bearing_deblur.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "sonar/beam_pattern.h"

namespace sonarcarve {
namespace {

// A pattern that keeps more than this share of a beam's power in the beam itself does not
// blur the image enough to take out: a beam as wide as its spacing keeps 94 % (1.6 %, -18 dB,
// in each neighbour and 1.4 % in the next), as a mission that gives no width is taken to;
// one 1.5 times as wide keeps 65 %.
constexpr double kSharpShare = 0.9;

double medianSpacing(const BearingTable& table) {
  std::vector<double> gaps;
  for (int b = 1; b < table.count(); ++b) {
    gaps.push_back(table.centre(b) - table.centre(b - 1));
  }
  if (gaps.empty()) {
    return 0.0;
  }
  const auto middle = gaps.begin() + static_cast<std::ptrdiff_t>(gaps.size() / 2);
  std::nth_element(gaps.begin(), middle, gaps.end());
  return *middle;
}

// One row's Richardson-Lucy deconvolution over the columns [lo, hi] of `row` (the rest of
// the row is dark). `exact`: every column of the image is data; otherwise lit ones only.
// Buffers hold the columns with `half` dark ones padded on each side, so that a convolution
// runs over whole arrays (tap by tap, which the compiler vectorises).
class RowDeconvolution {
 public:
  RowDeconvolution(const std::vector<float>& kernel, int cols)
      : k_(kernel), half_(static_cast<int>(kernel.size() / 2)), cols_(cols) {}

  void run(float* row, int lo, int hi, bool exact, int iterations) {
    const int n = hi - lo + 1;
    const auto padded = static_cast<std::size_t>(n + 2 * half_);
    obs_.assign(padded, 0.0f);
    std::copy(row + lo, row + hi + 1, obs_.begin() + half_);
    est_ = obs_;
    // The weight of the data each column is fitted to: the image's columns around it (all of
    // them for exact frames, the lit ones behind a detector; none beyond the image's edges).
    std::vector<float>& data = ratio_;
    data.assign(padded, 0.0f);
    for (int c = lo - half_; c <= hi + half_; ++c) {
      const auto i = static_cast<std::size_t>(c - lo + half_);
      data[i] = (c >= 0 && c < cols_ && (exact || obs_[i] > 0.0f)) ? 1.0f : 0.0f;
    }
    convolve(data, norm_);
    if (!exact) {
      // A dark pixel among lit ones starts at its neighbours' mean, weighted by the pattern,
      // so that it can hold its share of their blur (a missed return); started at 0 it would
      // stay there, and its lit neighbours would take its share.
      convolve(obs_, blur_);
      for (std::size_t i = 0; i < padded; ++i) {
        if (!(obs_[i] > 0.0f) && norm_[i] > 0.0f) {
          est_[i] = blur_[i] / norm_[i];
        }
      }
    }
    ratio_.assign(padded, 0.0f);
    for (int it = 0; it < iterations; ++it) {
      convolve(est_, blur_);
      for (std::size_t i = 0; i < padded; ++i) {
        ratio_[i] = obs_[i] > 0.0f && blur_[i] > 0.0f ? obs_[i] / blur_[i] : 0.0f;
      }
      convolve(ratio_, blur_);
      for (std::size_t i = 0; i < padded; ++i) {
        est_[i] = est_[i] > 0.0f ? est_[i] * blur_[i] / norm_[i] : 0.0f;
      }
    }
    for (int i = 0; i < n; ++i) {  // behind a detector, dark pixels stay dark
      const auto j = static_cast<std::size_t>(i + half_);
      row[lo + i] = exact || obs_[j] > 0.0f ? est_[j] : 0.0f;
    }
  }

 private:
  // out[i] = sum_d k[d] v[i + d] over the padded columns, v dark beyond them.
  void convolve(const std::vector<float>& v, std::vector<float>& out) const {
    const int size = static_cast<int>(v.size());
    out.assign(v.size(), 0.0f);
    for (int d = -half_; d <= half_; ++d) {
      const float w = k_[static_cast<std::size_t>(d + half_)];
      const int from = std::max(0, -d);
      const int to = std::min(size, size - d);
      const float* __restrict in = v.data() + d;
      float* __restrict o = out.data();
      for (int i = from; i < to; ++i) {
        o[i] += w * in[i];
      }
    }
  }

  const std::vector<float>& k_;
  int half_;
  int cols_;
  std::vector<float> obs_, est_, norm_, ratio_, blur_;
};

}  // namespace

BearingDeblur::BearingDeblur(const SonarModel& sonar)
    : width_rad_(sonar.horizontalBeamWidth()), spacing_rad_(medianSpacing(sonar.bearings())) {
  const double width = width_rad_;
  const double spacing = spacing_rad_;
  if (!(width > 0.0) || !(spacing > 0.0)) {
    return;
  }
  // The pattern to its second null, as far as the simulator traces it (sim/sonar_simulator.h).
  const SincSquaredBeam beam(width);
  const int half = std::min(static_cast<int>(beam.null(2) / spacing), sonar.cols() - 1);
  std::vector<double> weights;
  double total = 0.0;
  for (int d = -half; d <= half; ++d) {
    weights.push_back(beam.power(d * spacing));
    total += weights.back();
  }
  if (weights[static_cast<std::size_t>(half)] / total > kSharpShare) {
    return;
  }
  for (const double w : weights) {
    kernel_.push_back(static_cast<float>(w / total));
  }
}

std::string BearingDeblur::describe(bool exact_dark) const {
  if (!(width_rad_ > 0.0)) {
    return "off: the mission gives no horizontal beam width";
  }
  char text[160];
  const double width_deg = width_rad_ * 180.0 / std::numbers::pi;
  const double spacing_deg = spacing_rad_ * 180.0 / std::numbers::pi;
  if (!active()) {
    std::snprintf(text, sizeof text, "off: %.2f degree beams, %.2f degree apart, hardly blur",
                  width_deg, spacing_deg);
  } else {
    std::snprintf(text, sizeof text,
                  "%.2f degree beams, %.2f degree apart: their blur across bearing taken out of "
                  "every frame (%d iterations)",
                  width_deg, spacing_deg, exact_dark ? kExactIterations : kDetectedIterations);
  }
  return text;
}

cv::Mat BearingDeblur::apply(const cv::Mat& image, bool exact_dark) const {
  if (!active()) {
    return image;
  }
  cv::Mat out = cv::max(image, 0.0f);
  const int h = half();
  RowDeconvolution deconvolution(kernel_, out.cols);
  const int iterations = exact_dark ? kExactIterations : kDetectedIterations;
  for (int r = 0; r < out.rows; ++r) {
    float* row = out.ptr<float>(r);
    const auto lit = [](float v) { return v > 0.0f; };
    float* first = std::find_if(row, row + out.cols, lit);
    if (first == row + out.cols) {
      continue;
    }
    const auto last = std::find_if(std::make_reverse_iterator(row + out.cols),
                                   std::make_reverse_iterator(row), lit);
    const int lo = std::max(0, static_cast<int>(first - row) - h);
    const int hi = std::min(out.cols - 1, static_cast<int>(last.base() - row) - 1 + h);
    deconvolution.run(row, lo, hi, exact_dark, iterations);
  }
  return out;
}

}  // namespace sonarcarve
