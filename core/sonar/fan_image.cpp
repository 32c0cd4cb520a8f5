#include "sonar/fan_image.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "common/quantile.h"

namespace sonarcarve {
namespace {

cv::Mat toColour(const cv::Mat& polar, DisplayWindow w) {
  cv::Mat scaled;
  const double span = std::max(1e-6f, w.high - w.low);
  polar.convertTo(scaled, CV_8U, 255.0 / span, -w.low * 255.0 / span);
  cv::Mat colour;
  cv::applyColorMap(scaled, colour, cv::COLORMAP_INFERNO);
  return colour;
}

}  // namespace

DisplayWindow DisplayWindow::fromPercentiles(const cv::Mat& image) {
  std::vector<float> values(image.begin<float>(), image.end<float>());
  if (values.empty()) {
    return {};
  }
  // Sparse returns (a clean simulated frame) sit above the 99.5th percentile: keep the
  // brightest quarter of the range visible as well.
  const float brightest = *std::max_element(values.begin(), values.end());
  DisplayWindow w{quantile(values, 0.01), 0.0f};
  w.high = std::max(quantile(values, 0.995), 0.25f * brightest);
  if (w.high <= w.low) {
    w.high = w.low + 1.0f;
  }
  return w;
}

DisplayWindow DisplayWindow::fromQuantiles(const cv::Mat& image, double low_q, double high_q) {
  std::vector<float> values(image.begin<float>(), image.end<float>());
  if (values.empty()) {
    return {};
  }
  const float low = quantile(values, low_q);
  return {low, std::max(quantile(values, high_q), low + 1.0f)};
}

cv::Mat polarPicture(const cv::Mat& polar, DisplayWindow window) {
  cv::Mat flipped;
  cv::flip(polar, flipped, 0);
  return toColour(flipped, window);
}

cv::Mat fanPicture(const cv::Mat& polar, const SonarModel& sonar, DisplayWindow window,
                   int width_px, double ring_m) {
  const cv::Mat colour = toColour(polar, window);
  const double max_range = sonar.range().maxRange();
  const double left = sonar.bearings().leftEdge();
  const double right = sonar.bearings().rightEdge();
  // Horizontal extent of the fan, in metres, and the height it needs.
  const double half_width = max_range * std::max(std::sin(std::abs(left)), std::sin(right));
  const double top = max_range;
  const double bottom = std::min(0.0, max_range * std::min(std::cos(left), std::cos(right)));
  const double scale = width_px / (2.0 * half_width);  // pixels per metre
  const int height_px = static_cast<int>(std::ceil((top - bottom) * scale)) + 1;
  cv::Mat fan(height_px, width_px, CV_8UC3, cv::Scalar(40, 40, 40));
  const double apex_x = 0.5 * width_px;
  const double apex_y = top * scale;
  for (int y = 0; y < height_px; ++y) {
    for (int x = 0; x < width_px; ++x) {
      const double starboard = (x + 0.5 - apex_x) / scale;
      const double forward = (apex_y - (y + 0.5)) / scale;
      const auto pixel = sonar.pixelOf(Eigen::Vector3d(forward, starboard, 0.0));
      if (pixel) {
        fan.at<cv::Vec3b>(y, x) = colour.at<cv::Vec3b>(pixel->row, pixel->col);
      }
    }
  }
  const cv::Point apex(static_cast<int>(apex_x), static_cast<int>(apex_y));
  for (double r = ring_m; r < max_range + 1e-9; r += ring_m) {
    const int radius = static_cast<int>(r * scale);
    cv::ellipse(fan, apex, {radius, radius}, -90.0, left * 180.0 / M_PI, right * 180.0 / M_PI,
                cv::Scalar(160, 160, 160), 1, cv::LINE_AA);
    cv::putText(fan, cv::format("%g m", r),
                apex + cv::Point(static_cast<int>(radius * std::sin(right)) + 4,
                                 -static_cast<int>(radius * std::cos(right))),
                cv::FONT_HERSHEY_SIMPLEX, 0.4, cv::Scalar(200, 200, 200), 1, cv::LINE_AA);
  }
  return fan;
}

}  // namespace sonarcarve
