#include "frame_image.h"

#include <algorithm>

namespace sonarcarve::widgets {
DisplayWindow displayRange(const cv::Mat& image) {
  return DisplayWindow::fromQuantiles(image, 0.01, 0.998);
}

QImage polarImageToQImage(const cv::Mat& image, float low, float high, ColourMap map) {
  QImage out(image.cols, image.rows, QImage::Format_RGB32);
  const float span = high > low ? high - low : 1.0f;
  const ColourTable& colours = coloursOf(map);
  for (int r = 0; r < image.rows; ++r) {
    const float* in = image.ptr<float>(r);
    auto* line = reinterpret_cast<QRgb*>(out.scanLine(image.rows - 1 - r));
    for (int c = 0; c < image.cols; ++c) {
      const auto i =
          static_cast<std::size_t>(std::clamp((in[c] - low) / span, 0.0f, 1.0f) * 255.0f + 0.5f);
      line[c] = qRgb(colours[i][0], colours[i][1], colours[i][2]);
    }
  }
  return out;
}

}  // namespace sonarcarve::widgets
