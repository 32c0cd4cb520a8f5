// Polar frames stored as single-channel 16-bit PNG (lossless). Pixel values are the sonar's
// intensity counts: 8-bit sonars use 0..255, 16-bit sonars 0..65535.
#pragma once

#include <filesystem>
#include <opencv2/core.hpp>
#include <string>

namespace sonarcarve {

/// A CV_32F image as the sonar's whole counts (CV_16U), as a frame file holds it: values are
/// rounded to the nearest count; throws Error if one is NaN or outside [0, 65535] (`what` names
/// the frame in the message).
cv::Mat wholeCounts(const cv::Mat& image, const std::string& what);
/// Encodes a CV_32F image as 16-bit PNG bytes: its wholeCounts, losslessly.
std::string encodeFramePng(const cv::Mat& image, const std::string& what);
/// Reads an 8- or 16-bit single-channel PNG into a CV_32F image. Throws Error naming the file
/// if it is missing, empty, truncated, not a PNG or not single-channel.
cv::Mat readFramePng(const std::filesystem::path& path);

}  // namespace sonarcarve
