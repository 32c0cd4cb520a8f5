#include "pipeline/track_plan_svg.h"

#include <algorithm>
#include <cmath>

#include "pipeline/html_text.h"
#include "pipeline/map_pictures.h"

namespace sonarcarve {
namespace {

constexpr int kMargin = 30;
constexpr int kMaxHeight = 480;
constexpr std::size_t kMaxTrackPoints = 2000;

// (north, east) to the picture's (x, y): east to the right, north up.
struct PlanFrame {
  Eigen::Vector2d low;   // (north, east) at the bottom left
  double north_top = 0;  // north at the top margin
  double px_per_m = 1;
  Eigen::Vector2d at(const Eigen::Vector2d& ne) const {
    return {kMargin + (ne.y() - low.y()) * px_per_m, kMargin + (north_top - ne.x()) * px_per_m};
  }
  std::string point(const Eigen::Vector2d& ne) const {
    const Eigen::Vector2d xy = at(ne);
    return fixedText(xy.x(), 1) + "," + fixedText(xy.y(), 1);
  }
  // A marker circle at `ne` with its name as a tooltip; `paint` its fill and stroke.
  std::string circle(const Eigen::Vector2d& ne, const std::string& paint,
                     const std::string& name) const {
    const Eigen::Vector2d xy = at(ne);
    return "<circle cx=\"" + fixedText(xy.x(), 1) + "\" cy=\"" + fixedText(xy.y(), 1) +
           "\" r=\"5\" " + paint + "><title>" + name + "</title></circle>";
  }
};

std::string polyline(const std::vector<Eigen::Vector2d>& points, const PlanFrame& frame,
                     std::size_t step) {
  std::string text;
  for (std::size_t i = 0; i < points.size(); i += step) {
    text += frame.point(points[i]) + " ";
  }
  return text + frame.point(points.back());
}

std::string northArrow(int x, int y) {
  const std::string at = std::to_string(x) + "," + std::to_string(y);
  return "<g transform=\"translate(" + at +
         ")\"><polygon points=\"0,-22 7,4 0,-2 -7,4\" fill=\"#333\"/>"
         "<text x=\"0\" y=\"18\" text-anchor=\"middle\" font-size=\"13\">N</text></g>";
}

std::string scaleBar(double px_per_m, int width_px, int y) {
  const double metres = scaleBarLength(0.3 * (width_px - 2 * kMargin) / px_per_m);
  const std::string length = fixedText(metres * px_per_m, 1);
  const std::string x = std::to_string(kMargin);
  return "<g transform=\"translate(" + x + "," + std::to_string(y) +
         ")\"><path d=\"M0,-5 V5 M0,0 H" + length + " M" + length +
         ",-5 V5\" stroke=\"#333\" stroke-width=\"2\" fill=\"none\"/><text x=\"" + length +
         "\" dx=\"8\" y=\"5\" font-size=\"13\">" + escapeHtml(lengthLabel(metres)) + "</text></g>";
}

}  // namespace

std::string trackPlanSvg(const SurveyPlan& plan, const std::vector<Eigen::Vector3f>& points,
                         int width_px) {
  if (plan.track.empty()) {
    return {};
  }
  Eigen::Vector2d low = plan.track.front();
  Eigen::Vector2d high = plan.track.front();
  for (const auto& polygon : plan.footprints) {
    for (const Eigen::Vector2d& p : polygon) {
      low = low.cwiseMin(p);
      high = high.cwiseMax(p);
    }
  }
  for (const Eigen::Vector2d& p : plan.track) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  const Eigen::Vector2d extent = (high - low).cwiseMax(Eigen::Vector2d::Constant(1.0));
  PlanFrame frame{
      low, high.x(),
      std::min((width_px - 2.0 * kMargin) / extent.y(), (kMaxHeight - 2.0 * kMargin) / extent.x())};
  const int height_px = static_cast<int>(std::ceil(extent.x() * frame.px_per_m)) + 2 * kMargin;
  const int total_height = height_px + 30;
  std::string svg = "<svg class=\"plan\" width=\"" + std::to_string(width_px) + "\" height=\"" +
                    std::to_string(total_height) + "\" viewBox=\"0 0 " + std::to_string(width_px) +
                    " " + std::to_string(total_height) +
                    "\" font-family=\"sans-serif\" role=\"img\" aria-label=\"track plan\">"
                    "<rect width=\"100%\" height=\"" +
                    std::to_string(height_px) + "\" fill=\"#fbfbfd\" stroke=\"#ccc\"/>";
  // Opaque fans in a translucent group: their union, evenly pale however many overlap.
  svg += "<g fill=\"#2f7fd1\" opacity=\"0.25\" stroke=\"none\">";
  for (const auto& polygon : plan.footprints) {
    svg += "<polygon points=\"" + polyline(polygon, frame, 1) + "\"/>";
  }
  svg += "</g>";
  svg += "<g fill=\"#111\" fill-opacity=\"0.6\">";
  const std::size_t every = std::max<std::size_t>(1, points.size() / kMaxPlanPoints);
  for (std::size_t i = 0; i < points.size(); i += every) {
    const Eigen::Vector2d xy = frame.at(points[i].head<2>().cast<double>());
    svg += "<rect x=\"" + fixedText(xy.x() - 1.0, 1) + "\" y=\"" + fixedText(xy.y() - 1.0, 1) +
           "\" width=\"2\" height=\"2\"/>";
  }
  svg += "</g>";
  const std::size_t step = std::max<std::size_t>(1, plan.track.size() / kMaxTrackPoints);
  svg += "<polyline points=\"" + polyline(plan.track, frame, step) +
         "\" fill=\"none\" stroke=\"#c0392b\" stroke-width=\"2\"/>";
  svg += frame.circle(plan.track.front(), "fill=\"#27ae60\"", "start");
  svg +=
      frame.circle(plan.track.back(), "fill=\"none\" stroke=\"#c0392b\" stroke-width=\"2\"", "end");
  svg += northArrow(width_px - 24, 36);
  svg += scaleBar(frame.px_per_m, width_px, height_px + 16);
  return svg + "</svg>";
}

}  // namespace sonarcarve
