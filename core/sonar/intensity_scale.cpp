#include "sonar/intensity_scale.h"

#include <cmath>
#include <limits>

#include "common/error.h"
#include "common/number_text.h"

namespace sonarcarve {
namespace {

// F (x / F)^exponent of every pixel of a CV_32F image, negative ones taken as 0.
cv::Mat powerLaw(const cv::Mat& image, double full_scale, double exponent) {
  cv::Mat out;
  cv::max(image, 0.0f, out);
  out.convertTo(out, CV_32F, 1.0 / full_scale);
  cv::pow(out, exponent, out);
  out.convertTo(out, CV_32F, full_scale);
  return out;
}

double powerLaw(double value, double full_scale, double exponent) {
  return full_scale * std::pow(value / full_scale, exponent);
}

constexpr double kHalfCount = 0.5;

void requirePositiveCount(double full_scale_count) {
  if (!(full_scale_count > 0.0) || !std::isfinite(full_scale_count)) {
    throw Error("intensity scale", "full_scale_count",
                "expected a positive count, got " + shortestNumber(full_scale_count));
  }
}

void requireFloatImage(const cv::Mat& image) {
  if (image.type() != CV_32F) {
    throw Error("intensity scale", "image",
                "expected a CV_32F image, got OpenCV type " + std::to_string(image.type()));
  }
}

}  // namespace

IntensityScale IntensityScale::decibel(double full_scale_db, double full_scale_count) {
  if (!(full_scale_db > 0.0) || !std::isfinite(full_scale_db)) {
    throw Error("intensity scale", "full_scale_db",
                "expected a positive number of decibels, got " + shortestNumber(full_scale_db));
  }
  if (full_scale_db > kMostDecibels) {
    throw Error("intensity scale", "full_scale_db",
                "expected at most " + shortestNumber(kMostDecibels) +
                    " dB (the power must fit a float), got " + shortestNumber(full_scale_db));
  }
  requirePositiveCount(full_scale_count);
  IntensityScale scale;
  scale.full_scale_db_ = full_scale_db;
  scale.full_scale_count_ = full_scale_count;
  return scale;
}

IntensityScale IntensityScale::gamma(double gamma, double full_scale_count) {
  if (!(gamma > 0.0) || !(gamma <= kLargestGamma)) {
    throw Error("intensity scale", "gamma",
                "expected a gamma over 0 and at most " + shortestNumber(kLargestGamma) + ", got " +
                    shortestNumber(gamma));
  }
  requirePositiveCount(full_scale_count);
  const double smallest = std::log(kHalfCount / full_scale_count) /
                          std::log(std::numeric_limits<float>::min() / full_scale_count);
  if (!(gamma >= smallest)) {
    throw Error("intensity scale", "gamma",
                "expected a gamma of at least " + shortestNumber(std::ceil(smallest * 1e3) / 1e3) +
                    " for " + shortestNumber(full_scale_count) +
                    " counts full scale (half a count must stay a float's power), got " +
                    shortestNumber(gamma));
  }
  IntensityScale scale;
  if (gamma != 1.0) {
    scale.gamma_ = gamma;
    scale.full_scale_count_ = full_scale_count;
  }
  return scale;
}

double IntensityScale::darkPower() const {
  if (isLinear()) {
    return kHalfCount;
  }
  if (isDecibel()) {
    return std::pow(10.0, kHalfCount * full_scale_db_ / full_scale_count_ / 10.0);
  }
  return powerLaw(kHalfCount, full_scale_count_, 1.0 / gamma_);
}

double IntensityScale::fullScalePower() const {
  if (isLinear()) {
    return 0.0;
  }
  return isDecibel() ? std::pow(10.0, full_scale_db_ / 10.0) : full_scale_count_;
}

std::string IntensityScale::describe() const {
  if (isLinear()) {
    return "linear";
  }
  if (!isDecibel()) {
    return "gamma " + shortestNumber(gamma_) + " (" + shortestNumber(full_scale_count_) +
           " counts full scale)";
  }
  return "decibel (" + shortestNumber(full_scale_count_) +
         " counts = " + shortestNumber(full_scale_db_) + " dB)";
}

void IntensityScale::countsToPower(cv::Mat& image, const std::string& what,
                                   const std::string& place) const {
  requireFloatImage(image);
  if (isLinear()) {
    return;
  }
  double most = 0.0;
  cv::Point at;
  cv::minMaxLoc(image, nullptr, &most, nullptr, &at);
  if (most > full_scale_count_) {
    throw Error(
        what,
        (place.empty() ? "" : place + ", ") + "range bin " + std::to_string(at.y) + ", beam " +
            std::to_string(at.x),
        "count " + shortestNumber(most) + " is over the sonar's full scale (" + describe() + ")");
  }
  if (!isDecibel()) {
    // power = F (count / F)^(1 / gamma); negative counts (none a sonar sends) are no echo.
    image = powerLaw(image, full_scale_count_, 1.0 / gamma_);
    return;
  }
  // power = exp(count * ln(10) * dB_per_count / 10); count 0, the bottom of the scale, is no
  // echo at all (a noise-free frame's empty water must stay dark, not become a floor of 1).
  const cv::Mat no_echo = image <= 0.0f;
  const double nepers_per_count = std::log(10.0) * full_scale_db_ / full_scale_count_ / 10.0;
  image.convertTo(image, CV_32F, nepers_per_count);
  cv::exp(image, image);
  image.setTo(0.0f, no_echo);
}

cv::Mat IntensityScale::powerToCounts(const cv::Mat& image) const {
  requireFloatImage(image);
  if (isLinear()) {
    return image.clone();
  }
  if (!isDecibel()) {
    return powerLaw(image, full_scale_count_, gamma_);
  }
  cv::Mat counts;
  cv::max(image, 1.0f, counts);  // powers up to count 1's, and no echo, are count 0
  cv::log(counts, counts);
  const double counts_per_neper = full_scale_count_ * 10.0 / (full_scale_db_ * std::log(10.0));
  counts.convertTo(counts, CV_32F, counts_per_neper);
  return counts;
}

}  // namespace sonarcarve
