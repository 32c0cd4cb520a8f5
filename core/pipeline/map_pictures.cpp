#include "pipeline/map_pictures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <opencv2/imgproc.hpp>

namespace sonarcarve {
namespace {

constexpr int kMargin = 24;  // around the drawing, px
constexpr int kFooter = 44;  // below it: scale bar and colour key
constexpr int kMaxHeight = 460;
const cv::Scalar kInk(60, 60, 60);

// One view: the picture's axes as (right, down) combinations of (north, east, down), the
// direction shown at each side, and the coordinate whose largest values are nearest.
struct Side {
  const char* title;
  Eigen::Vector3d right;
  Eigen::Vector3d down;
  Eigen::Vector3d towards_viewer;
  const char* left_label;
  const char* right_label;
  const char* top_label;
};

const Side kSides[] = {
    {"From above (north up)", {0, 1, 0}, {-1, 0, 0}, {0, 0, -1}, "W", "E", "N"},
    {"From the north (looking south)", {0, -1, 0}, {0, 0, 1}, {1, 0, 0}, "E", "W", "up"},
    {"From the east (looking west)", {1, 0, 0}, {0, 0, 1}, {0, 1, 0}, "S", "N", "up"},
};

void text(cv::Mat& image, const std::string& words, cv::Point at, double scale = 0.45) {
  cv::putText(image, words, at, cv::FONT_HERSHEY_SIMPLEX, scale, kInk, 1, cv::LINE_AA);
}

int textWidth(const std::string& words, double scale = 0.45) {
  int baseline = 0;
  return cv::getTextSize(words, cv::FONT_HERSHEY_SIMPLEX, scale, 1, &baseline).width;
}

// Viridis colours for heights from `low` to `high` (metres up).
class HeightColours {
 public:
  HeightColours(double low, double high) : low_(low), span_(std::max(high - low, 1e-6)) {
    cv::Mat ramp(1, 256, CV_8U);
    for (int i = 0; i < 256; ++i) {
      ramp.at<std::uint8_t>(0, i) = static_cast<std::uint8_t>(i);
    }
    cv::applyColorMap(ramp, table_, cv::COLORMAP_VIRIDIS);
  }
  cv::Scalar at(double height) const {
    const int i =
        std::clamp(static_cast<int>(std::lround(255.0 * (height - low_) / span_)), 0, 255);
    const cv::Vec3b c = table_.at<cv::Vec3b>(0, i);
    return {static_cast<double>(c[0]), static_cast<double>(c[1]), static_cast<double>(c[2])};
  }
  double low() const { return low_; }
  double high() const { return low_ + span_; }

 private:
  double low_;
  double span_;
  cv::Mat table_;
};

void drawScaleBar(cv::Mat& image, double px_per_m, int y) {
  const double metres = scaleBarLength(0.3 * (image.cols - 2 * kMargin) / px_per_m);
  const int length = static_cast<int>(std::lround(metres * px_per_m));
  const cv::Point start(kMargin, y);
  cv::line(image, start, start + cv::Point(length, 0), kInk, 2);
  for (const int x : {0, length}) {
    cv::line(image, start + cv::Point(x, -5), start + cv::Point(x, 5), kInk, 1);
  }
  text(image, lengthLabel(metres), start + cv::Point(length + 8, 5));
}

std::string heightLabel(double metres) {
  char label[32];
  std::snprintf(label, sizeof label, "%.1f m", metres);
  return label;
}

void drawColourKey(cv::Mat& image, const HeightColours& colours, int y) {
  const int width = 120;
  const std::string high = heightLabel(colours.high());
  const int x1 = image.cols - kMargin - textWidth(high) - 8;
  const int x0 = x1 - width;
  for (int x = 0; x < width; ++x) {
    const double height = colours.low() + (colours.high() - colours.low()) * x / (width - 1);
    cv::line(image, {x0 + x, y - 6}, {x0 + x, y + 6}, colours.at(height), 1);
  }
  text(image, high, {x1 + 6, y + 5});
  const std::string low = "height " + heightLabel(colours.low());
  text(image, low, {x0 - 6 - textWidth(low), y + 5});
}

MapPicture drawSide(const std::vector<Eigen::Vector3f>& points, const Side& side,
                    const HeightColours& colours, double voxel_m, int width_px) {
  Eigen::Vector2d low = Eigen::Vector2d::Constant(INFINITY);
  Eigen::Vector2d high = Eigen::Vector2d::Constant(-INFINITY);
  std::vector<Eigen::Vector2d> at(points.size());
  std::vector<double> nearness(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d p = points[i].cast<double>();
    at[i] = {side.right.dot(p), side.down.dot(p)};
    nearness[i] = side.towards_viewer.dot(p);
    low = low.cwiseMin(at[i]);
    high = high.cwiseMax(at[i]);
  }
  const Eigen::Vector2d extent = (high - low).cwiseMax(Eigen::Vector2d::Constant(voxel_m));
  const double px_per_m =
      std::min((width_px - 2.0 * kMargin) / extent.x(), (kMaxHeight - 2.0 * kMargin) / extent.y());
  const int height_px = static_cast<int>(std::ceil(extent.y() * px_per_m)) + 2 * kMargin;
  MapPicture picture{side.title,
                     cv::Mat(height_px + kFooter, width_px, CV_8UC3, cv::Scalar(255, 255, 255))};
  cv::Mat& image = picture.image;
  // Centred across; the drawing's edges at the margins along its longer fit.
  const double x_offset = 0.5 * (width_px - extent.x() * px_per_m);
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return nearness[a] < nearness[b]; });
  const int square = std::max(2, static_cast<int>(std::ceil(voxel_m * px_per_m)));
  for (const std::size_t i : order) {
    const int x = static_cast<int>(std::lround(x_offset + (at[i].x() - low.x()) * px_per_m));
    const int y = static_cast<int>(std::lround(kMargin + (at[i].y() - low.y()) * px_per_m));
    const cv::Point corner(x - square / 2, y - square / 2);
    cv::rectangle(image, cv::Rect(corner, cv::Size(square, square)),
                  colours.at(-static_cast<double>(points[i].z())), cv::FILLED);
  }
  cv::rectangle(image, cv::Rect(0, 0, width_px, height_px), cv::Scalar(200, 200, 200), 1);
  text(image, side.left_label, {6, height_px / 2 + 5});
  text(image, side.right_label, {width_px - 6 - textWidth(side.right_label), height_px / 2 + 5});
  text(image, side.top_label, {width_px / 2 - textWidth(side.top_label) / 2, 16});
  drawScaleBar(image, px_per_m, height_px + kFooter / 2);
  drawColourKey(image, colours, height_px + kFooter / 2);
  return picture;
}

}  // namespace

double scaleBarLength(double max_m) {
  if (!(max_m > 0.0)) {
    return 0.0;
  }
  const double decade = std::pow(10.0, std::floor(std::log10(max_m)));
  for (const double step : {5.0, 2.0, 1.0}) {
    if (step * decade <= max_m) {
      return step * decade;
    }
  }
  return decade;
}

std::string lengthLabel(double metres) {
  char label[32];
  if (metres >= 1000.0) {
    std::snprintf(label, sizeof label, "%g km", metres / 1000.0);
  } else if (metres >= 1.0) {
    std::snprintf(label, sizeof label, "%g m", metres);
  } else if (metres >= 0.01) {
    std::snprintf(label, sizeof label, "%g cm", metres * 100.0);
  } else {
    std::snprintf(label, sizeof label, "%g mm", metres * 1000.0);
  }
  return label;
}

std::vector<MapPicture> mapPictures(const std::vector<Eigen::Vector3f>& points, double voxel_m,
                                    int width_px) {
  std::vector<MapPicture> pictures;
  if (points.empty()) {
    return pictures;
  }
  double low = INFINITY;
  double high = -INFINITY;
  for (const Eigen::Vector3f& p : points) {
    low = std::min(low, -static_cast<double>(p.z()));
    high = std::max(high, -static_cast<double>(p.z()));
  }
  const HeightColours colours(low, high);
  for (const Side& side : kSides) {
    pictures.push_back(drawSide(points, side, colours, voxel_m, width_px));
  }
  return pictures;
}

}  // namespace sonarcarve
