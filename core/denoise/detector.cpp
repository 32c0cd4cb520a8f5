#include "denoise/detector.h"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "common/error.h"

namespace sonarcarve {
namespace {

// What a pixel the Z-test keeps reads at least (counts).
constexpr float kDetectedMinimum = 1.0f;

// Each pixel's median with its neighbours in bearing, on the same range bin (edge beams
// repeat themselves).
cv::Mat medianAcrossBeams(const cv::Mat& image) {
  cv::Mat padded;
  cv::copyMakeBorder(image, padded, 0, 0, 1, 1, cv::BORDER_REPLICATE);
  const cv::Mat left = padded.colRange(0, image.cols);
  const cv::Mat centre = padded.colRange(1, image.cols + 1);
  const cv::Mat right = padded.colRange(2, image.cols + 2);
  cv::Mat low, high, median;
  cv::min(left, centre, low);
  cv::max(left, centre, high);
  cv::min(high, right, high);
  cv::max(low, high, median);
  return median;
}

}  // namespace

DetectorParams DetectorParams::resolved(bool have_noise_model) const {
  DetectorParams p = *this;
  if (p.mode == DetectorMode::Auto) {
    p.mode = have_noise_model ? DetectorMode::ZTest : DetectorMode::None;
  }
  return p;
}

void DetectorParams::validate() const {
  if (!hasName(mode)) {
    throw Error("parameters", "detector.mode", "expected auto, none, ztest or cfar");
  }
  if (const auto problem = smoothingProblem(smoothing)) {
    throw Error("parameters", "detector.smoothing", *problem);
  }
  if (cfar_guard < 0 || cfar_train < 1) {
    throw Error("parameters", "detector.cfar", "expected guard >= 0 and train >= 1 cells");
  }
  if (!(cfar_pfa > 0.0 && cfar_pfa < 1.0)) {
    throw Error("parameters", "detector.cfar_pfa", "expected a probability in (0, 1)");
  }
}

Detector::Detector(DetectorParams params, std::shared_ptr<const NoiseModel> model,
                   const SonarModel& sonar)
    : params_(params.resolved(model != nullptr)), model_(std::move(model)) {
  params_.validate();
  if (params_.needsNoiseModel()) {
    if (!model_) {
      throw Error("parameters", "detector." + std::string(toString(params_.mode)),
                  "needs a noise model (sonarcarve-cli noise-model EMPTY_WATER_MISSION)");
    }
    model_->checkGeometry(sonar, "detector");
    if (model_->smoothing() != params_.smoothing) {
      throw Error("detector", "noise model",
                  "learned with smoothing " + std::to_string(model_->smoothing()) +
                      ", the detector smooths with " + std::to_string(params_.smoothing) +
                      ": learn it again with the same smoothing");
    }
    threshold_ = model_->mean() + params_.z * model_->stddev();
  }
}

cv::Mat Detector::apply(const cv::Mat& image) const {
  if (params_.mode == DetectorMode::ZTest) {
    return zTest(image);
  }
  if (params_.mode == DetectorMode::Cfar) {
    return cfar(image);
  }
  return image;
}

cv::Mat Detector::zTest(const cv::Mat& image) const {
  // (I - mean) / std > z on the smoothed frame. Smoothing spreads a return into its
  // neighbours: a pixel is kept only where its own intensity is also above the mean.
  cv::Mat keep = smoothFrame(image, params_.smoothing) > threshold_;
  if (params_.smoothing > 1) {
    keep &= image > model_->mean();
  }
  // A kept pixel carries its return's estimate, not the noise under it: the median of its
  // beam and the two beside it, less the noise's mean. The median takes the speckle's
  // deepest dip out without spreading a bright neighbour's return into it. At least one
  // count: the pixel was detected, and the seed paper's minimum carves only what reads 0.
  cv::Mat signal = medianAcrossBeams(image) - model_->mean();
  signal = cv::max(signal, kDetectedMinimum);
  cv::Mat out(image.size(), CV_32F, cv::Scalar(0.0f));
  signal.copyTo(out, keep);
  return out;
}

cv::Mat Detector::backgroundSigma() const {
  if (params_.mode != DetectorMode::ZTest) {
    return {};
  }
  return model_->stddev() * static_cast<double>(params_.smoothing);
}

double Detector::cfarAlpha() const {
  const double n = 2.0 * params_.cfar_train;
  return n * (std::pow(params_.cfar_pfa, -1.0 / n) - 1.0);
}

cv::Mat Detector::cfar(const cv::Mat& original) const {
  const cv::Mat image = smoothFrame(original, params_.smoothing);
  const int rows = image.rows;
  const int guard = params_.cfar_guard;
  const int train = params_.cfar_train;
  const auto alpha = static_cast<float>(cfarAlpha());
  cv::Mat out(image.size(), CV_32F, cv::Scalar(0.0f));
  std::vector<double> prefix(static_cast<std::size_t>(rows) + 1);
  for (int c = 0; c < image.cols; ++c) {
    // Prefix sums of the power along this beam make each window O(1).
    for (int r = 0; r < rows; ++r) {
      const double v = image.at<float>(r, c);
      prefix[static_cast<std::size_t>(r) + 1] = prefix[static_cast<std::size_t>(r)] + v * v;
    }
    const auto windowSum = [&](int from, int to) {  // [from, to), clamped to the beam
      from = std::clamp(from, 0, rows);
      to = std::clamp(to, 0, rows);
      return std::pair{
          prefix[static_cast<std::size_t>(to)] - prefix[static_cast<std::size_t>(from)], to - from};
    };
    for (int r = 0; r < rows; ++r) {
      const auto [near_sum, near_n] = windowSum(r - guard - train, r - guard);
      const auto [far_sum, far_n] = windowSum(r + guard + 1, r + guard + 1 + train);
      const int n = near_n + far_n;
      if (n == 0) {
        continue;
      }
      const double noise = (near_sum + far_sum) / n;
      const float v = image.at<float>(r, c);
      if (static_cast<double>(v) * v > alpha * noise) {
        out.at<float>(r, c) = original.at<float>(r, c);
      }
    }
  }
  return out;
}

}  // namespace sonarcarve
