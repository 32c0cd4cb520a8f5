#include "colour_maps.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>

namespace sonarcarve::widgets {
namespace {

template <typename F>
ColourTable tableOf(F colour) {
  ColourTable t{};
  for (int i = 0; i < 256; ++i) {
    t[static_cast<std::size_t>(i)] = colour(i);
  }
  return t;
}

}  // namespace

const ColourTable& copperColours() {
  static const ColourTable table = tableOf([](int v) {
    return Rgb{static_cast<unsigned char>(std::min(255, v * 5 / 4)),
               static_cast<unsigned char>(v * 4 / 5), static_cast<unsigned char>(v / 2)};
  });
  return table;
}

const ColourTable& greyColours() {
  static const ColourTable table = tableOf([](int v) {
    const auto g = static_cast<unsigned char>(v);
    return Rgb{g, g, g};
  });
  return table;
}

const ColourTable& viridisColours() {
  static const ColourTable table = [] {
    cv::Mat ramp(1, 256, CV_8U);
    for (int i = 0; i < 256; ++i) {
      ramp.at<unsigned char>(0, i) = static_cast<unsigned char>(i);
    }
    cv::Mat bgr;
    cv::applyColorMap(ramp, bgr, cv::COLORMAP_VIRIDIS);
    return tableOf([&](int i) {
      const cv::Vec3b c = bgr.at<cv::Vec3b>(0, i);
      return Rgb{c[2], c[1], c[0]};
    });
  }();
  return table;
}

const ColourTable& errorColours() {
  static const ColourTable table = tableOf([](int i) {
    // 0..127: green to yellow; 128..255: yellow to red.
    const int r = i < 128 ? 60 + i * 195 / 127 : 255;
    const int g = i < 128 ? 200 + i * 30 / 127 : 230 - (i - 128) * 190 / 127;
    return Rgb{static_cast<unsigned char>(r), static_cast<unsigned char>(g),
               static_cast<unsigned char>(50)};
  });
  return table;
}

const ColourTable& coloursOf(ColourMap map) {
  return map == ColourMap::Grey ? greyColours() : copperColours();
}

}  // namespace sonarcarve::widgets
