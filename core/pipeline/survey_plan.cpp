#include "pipeline/survey_plan.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace sonarcarve {
namespace {

constexpr int kArcPoints = 16;

std::vector<Eigen::Vector2d> footprint(const PosedFrame& frame, const SonarModel& sonar) {
  const BearingTable& bearings = sonar.bearings();
  std::vector<Eigen::Vector2d> polygon;
  for (const double range : {sonar.range().min_m, sonar.range().maxRange()}) {
    const bool far = range > sonar.range().min_m;
    for (int i = 0; i <= kArcPoints; ++i) {
      const double t = static_cast<double>(far ? kArcPoints - i : i) / kArcPoints;
      const double bearing = bearings.leftEdge() + t * (bearings.rightEdge() - bearings.leftEdge());
      const Eigen::Vector3d p = frame.T_world_sonar * pointFromPolar({range, bearing, 0.0});
      polygon.emplace_back(p.x(), p.y());
    }
  }
  return polygon;
}

// The area covered by the union of `polygons`, rasterised on a grid of about 500 cells a side.
double unionArea(const std::vector<std::vector<Eigen::Vector2d>>& polygons) {
  Eigen::Vector2d low = Eigen::Vector2d::Constant(INFINITY);
  Eigen::Vector2d high = Eigen::Vector2d::Constant(-INFINITY);
  for (const auto& polygon : polygons) {
    for (const Eigen::Vector2d& p : polygon) {
      low = low.cwiseMin(p);
      high = high.cwiseMax(p);
    }
  }
  const double extent = (high - low).maxCoeff();
  if (!(extent > 0.0)) {
    return 0.0;
  }
  const double cell = extent / 500.0;
  const Eigen::Vector2i cells = ((high - low) / cell).array().ceil().cast<int>() + 1;
  cv::Mat covered = cv::Mat::zeros(cells.x(), cells.y(), CV_8U);
  for (const auto& polygon : polygons) {
    std::vector<cv::Point> corners;
    for (const Eigen::Vector2d& p : polygon) {
      const Eigen::Vector2d at = (p - low) / cell;
      corners.emplace_back(static_cast<int>(std::lround(at.y())),
                           static_cast<int>(std::lround(at.x())));
    }
    cv::fillPoly(covered, std::vector<std::vector<cv::Point>>{corners}, cv::Scalar(1));
  }
  return static_cast<double>(cv::countNonZero(covered)) * cell * cell;
}

}  // namespace

SurveyPlan surveyPlan(const std::vector<PosedFrame>& frames, const SonarModel& sonar) {
  SurveyPlan plan;
  if (frames.empty()) {
    return plan;
  }
  plan.depth_min_m = INFINITY;
  plan.depth_max_m = -INFINITY;
  std::vector<std::vector<Eigen::Vector2d>> every_fan;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const Eigen::Vector3d at = frames[i].T_world_sonar.translation();
    plan.track.emplace_back(at.x(), at.y());
    if (i > 0) {
      plan.track_length_m += (at - frames[i - 1].T_world_sonar.translation()).norm();
    }
    plan.depth_min_m = std::min(plan.depth_min_m, at.z());
    plan.depth_max_m = std::max(plan.depth_max_m, at.z());
    every_fan.push_back(footprint(frames[i], sonar));
  }
  plan.coverage_area_m2 = unionArea(every_fan);
  const std::size_t shown = std::min(frames.size(), SurveyPlan::kMaxFootprints);
  for (std::size_t k = 0; k < shown; ++k) {
    plan.footprints.push_back(
        every_fan[k * (frames.size() - 1) / std::max<std::size_t>(1, shown - 1)]);
  }
  return plan;
}

}  // namespace sonarcarve
