// Frame: one polar sonar image with its time and the sonar that took it.
// image: CV_32F, rows = range bins (near to far), cols = beams (port to starboard), values
// are the echo's power: the sonar's counts (0..255 for 8-bit sonars, 0..65535 for 16-bit) as
// they are when its intensity scale is linear, converted by readers when it is decibel
// (sonar/intensity_scale.h).
#pragma once

#include <opencv2/core.hpp>
#include <string>

namespace sonarcarve {

struct Frame {
  double time_s = 0.0;   ///< seconds, on the navigation's clock
  std::string sonar_id;  ///< SonarModel::id() of the sonar that took it
  cv::Mat image;         ///< CV_32F, SonarModel::rows() x SonarModel::cols()
};

}  // namespace sonarcarve
