#include "sonar/bearing_deblur.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <opencv2/imgproc.hpp>

#include "common/angles.h"
#include "common/error.h"
#include "sonar/beam_pattern.h"

namespace sonarcarve {
namespace {

// A pattern that keeps more than this share of a beam's power in the beam itself does not
// blur the image enough to take out. Averaged over each beam's interval (as the simulator's
// sub-rays sample it), a beam half as wide as its spacing keeps 94 %, one as wide 79 % (9 % in
// each neighbour) and one five times as wide 19 %.
constexpr double kSharpShare = 0.9;
// Estimates that fall this far under their row's brightest are dark: repeated products
// would otherwise reach denormal floats, slow to compute with.
constexpr float kNegligible = 1e-7f;

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
    // Unknown sources start at their lit neighbours' mean, weighted by the pattern, so that
    // they can hold their share of the blur; started at 0 they would stay there, and their
    // neighbours would take their share. They are a detector's dark pixels (a missed return)
    // and, in every frame, the bearings just beyond the fan, whose returns its edge beams
    // still image.
    convolve(obs_, blur_);
    for (int c = lo - half_; c <= hi + half_; ++c) {
      const auto i = static_cast<std::size_t>(c - lo + half_);
      const bool unknown = c < 0 || c >= cols_ || (!exact && !(obs_[i] > 0.0f));
      if (unknown && norm_[i] > 0.0f) {
        est_[i] = blur_[i] / norm_[i];
      }
    }
    const float floor = kNegligible * *std::max_element(obs_.begin(), obs_.end());
    ratio_.assign(padded, 0.0f);
    for (int it = 0; it < iterations; ++it) {
      convolve(est_, blur_);
      for (std::size_t i = 0; i < padded; ++i) {
        ratio_[i] = obs_[i] > 0.0f && blur_[i] > 0.0f ? obs_[i] / blur_[i] : 0.0f;
      }
      convolve(ratio_, blur_);
      for (std::size_t i = 0; i < padded; ++i) {
        const float e = est_[i] > 0.0f && norm_[i] > 0.0f ? est_[i] * blur_[i] / norm_[i] : 0.0f;
        est_[i] = e > floor ? e : 0.0f;
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
      const int from = std::max(0, -d);  // out[from + j] takes v[from + d + j]
      const int count = std::min(size, size - d) - from;
      const float* __restrict in = v.data() + (from + d);
      float* __restrict o = out.data() + from;
      for (int j = 0; j < count; ++j) {
        o[j] += w * in[j];
      }
    }
  }

  const std::vector<float>& k_;
  int half_;
  int cols_;
  std::vector<float> obs_, est_, norm_, ratio_, blur_;
};

}  // namespace

std::vector<float> bearingBlurKernel(double width_rad, double spacing_rad, int max_half) {
  const std::vector<double> weights =
      meansOverBeams(SincSquaredBeam(width_rad), spacing_rad, max_half, false);
  double total = 0.0;
  for (const double w : weights) {
    total += w;
  }
  std::vector<float> kernel;
  for (const double w : weights) {
    kernel.push_back(static_cast<float>(w / total));
  }
  return kernel;
}

BearingDeblur::BearingDeblur(const SonarModel& sonar)
    : width_rad_(sonar.horizontalBeamWidth()),
      spacing_rad_(sonar.bearings().medianSpacing()),
      dark_power_(static_cast<float>(sonar.intensityScale().darkPower())) {
  if (!(width_rad_ > 0.0) || !(spacing_rad_ > 0.0)) {
    return;
  }
  std::vector<float> kernel = bearingBlurKernel(width_rad_, spacing_rad_, sonar.cols() - 1);
  if (kernel[kernel.size() / 2] <= kSharpShare) {
    kernel_ = std::move(kernel);
  }
}

std::string BearingDeblur::describe(bool exact_dark) const {
  if (!(width_rad_ > 0.0)) {
    return "off: the mission gives no horizontal beam width";
  }
  char text[160];
  const double width_deg = radToDeg(width_rad_);
  const double spacing_deg = radToDeg(spacing_rad_);
  if (!active()) {
    std::snprintf(text, sizeof text, "off: %.2f degree beams, %.2f degree apart, hardly blur",
                  width_deg, spacing_deg);
  } else {
    std::snprintf(text, sizeof text,
                  "%.2f degree beams, %.2f degree apart: their blur across bearing taken out of "
                  "every frame (%d iterations%s)",
                  width_deg, spacing_deg, exact_dark ? kExactIterations : kDetectedIterations,
                  exact_dark ? "; what is left under half a count is dark" : "");
  }
  return text;
}

cv::Mat BearingDeblur::apply(const cv::Mat& image, bool exact_dark) const {
  if (!active()) {
    return image;
  }
  if (image.type() != CV_32FC1) {
    throw Error("bearing deblur", "frame", "expected a single-channel float image");
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
  if (exact_dark) {
    cv::threshold(out, out, dark_power_, 0.0, cv::THRESH_TOZERO);
  }
  return out;
}

}  // namespace sonarcarve
