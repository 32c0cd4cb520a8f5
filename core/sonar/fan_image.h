// Pictures of a polar frame for people: the polar image itself and the fan in true geometry
// (sonar at the bottom centre, range upwards, port on the left), as 8-bit colour images with
// OpenCV's colour maps. Intensities are mapped linearly from [low, high].
#pragma once

#include <opencv2/core.hpp>

#include "sonar/sonar_model.h"

namespace sonarcarve {

struct DisplayWindow {
  float low = 0.0f;
  float high = 255.0f;
  /// From the 1st percentile to the larger of the 99.5th percentile and a quarter of the max.
  static DisplayWindow fromPercentiles(const cv::Mat& image);
  /// From the `low_q` to the `high_q` quantile (for live views: a few saturated specular
  /// returns must not darken a whole frame); at least one count wide.
  static DisplayWindow fromQuantiles(const cv::Mat& image, double low_q, double high_q);
};

/// Polar image as BGR, nearest range at the bottom, one pixel per bin and beam.
cv::Mat polarPicture(const cv::Mat& polar, DisplayWindow window);
/// The fan in true geometry, `width_px` wide, with range rings every `ring_m` metres.
cv::Mat fanPicture(const cv::Mat& polar, const SonarModel& sonar, DisplayWindow window,
                   int width_px = 900, double ring_m = 1.0);

}  // namespace sonarcarve
