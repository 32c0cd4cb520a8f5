#include "frame_image.h"

#include <algorithm>

namespace sonarcarve::widgets {
namespace {

QRgb colourOf(float u, ColourMap map) {
  const int v = static_cast<int>(std::clamp(u, 0.0f, 1.0f) * 255.0f + 0.5f);
  if (map == ColourMap::Grey) {
    return qRgb(v, v, v);
  }
  // Copper: black -> orange -> pale, the classic sonar look.
  return qRgb(std::min(255, v * 5 / 4), v * 4 / 5, v / 2);
}

}  // namespace

QImage polarImageToQImage(const cv::Mat& image, float low, float high, ColourMap map) {
  QImage out(image.cols, image.rows, QImage::Format_RGB32);
  const float span = high > low ? high - low : 1.0f;
  for (int r = 0; r < image.rows; ++r) {
    const float* in = image.ptr<float>(r);
    auto* line = reinterpret_cast<QRgb*>(out.scanLine(image.rows - 1 - r));
    for (int c = 0; c < image.cols; ++c) {
      line[c] = colourOf((in[c] - low) / span, map);
    }
  }
  return out;
}

}  // namespace sonarcarve::widgets
