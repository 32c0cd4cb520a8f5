// Polar frames stored as single-channel 16-bit PNG (lossless). Pixel values are the sonar's
// intensity counts: 8-bit sonars use 0..255, 16-bit sonars 0..65535.
#pragma once

#include <filesystem>
#include <opencv2/core.hpp>
#include <optional>
#include <string>

namespace sonarcarve {

/// A CV_32F image as the sonar's whole counts (CV_16U), as a frame file holds it: values are
/// rounded to the nearest count; throws Error if one is NaN or outside [0, 65535] (`what` names
/// the frame in the message).
cv::Mat wholeCounts(const cv::Mat& image, const std::string& what);
/// Encodes a CV_32F image as 16-bit PNG bytes: its wholeCounts, losslessly.
std::string encodeFramePng(const cv::Mat& image, const std::string& what);
/// The size a frame must have: the sonar's range bins x beams.
struct FrameShape {
  int rows = 0;
  int cols = 0;
};

/// Reads an 8- or 16-bit single-channel PNG into a CV_32F image. Throws Error naming the file
/// if it is missing, empty, truncated, not a PNG or not single-channel; if its header declares
/// another size than `expected` (when given), or more than the largest frame; if the file is
/// larger than a PNG of that size can be (input_limits.h); or if its image data inflates to
/// more than the size it declares. Work and memory are bounded by the size declared: nothing is
/// decoded before these checks, and the decoder stops at the declared size.
cv::Mat readFramePng(const std::filesystem::path& path,
                     std::optional<FrameShape> expected = std::nullopt);

}  // namespace sonarcarve
