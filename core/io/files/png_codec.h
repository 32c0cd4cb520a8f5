// PNG images in memory, with libpng: the frames of a mission folder (16-bit grey) and the
// pictures the CLI draws (8-bit grey or colour). libpng directly rather than OpenCV's
// imgcodecs: imgcodecs brings GDAL, GDCM and their dependencies (140 libraries) into every
// process that links it, 50 MB of resident memory and 0.1 s of start-up per command
// (docs/benchmarks.md, "Memory"), for the one format we use.
#pragma once

#include <opencv2/core.hpp>
#include <string>

namespace sonarcarve {

/// PNG bytes of a CV_8UC1, CV_16UC1 or CV_8UC3 (blue, green, red) image. Throws Error
/// naming `what` for another type or an empty image.
std::string encodePng(const cv::Mat& image, const std::string& what);

/// Decodes a greyscale PNG (1 to 16 bits, no alpha) into a CV_8UC1 or CV_16UC1 image.
/// Throws Error naming `file` and what is wrong: a corrupt or cut-off stream, or colour.
cv::Mat decodeGreyPng(const std::string& bytes, const std::string& file);

}  // namespace sonarcarve
