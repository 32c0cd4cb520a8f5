// The survey in plan, for the report: where the sonar went (the track of the frames a run
// placed) and what its fans swept (each frame's fan at zero elevation, seen from above), with
// the figures report.json gives of them (docs/formats.md, "report.json").
#pragma once

#include <Eigen/Core>
#include <vector>

#include "pipeline/frame_stage.h"
#include "sonar/sonar_model.h"

namespace sonarcarve {

struct SurveyPlan {
  /// (north, east) of the sonar at each placed frame, in the run's local frame, metres.
  std::vector<Eigen::Vector2d> track;
  /// The fans of at most kMaxFootprints frames spread over the track, as (north, east)
  /// polygons: the fan's near arc, then its far arc back.
  std::vector<std::vector<Eigen::Vector2d>> footprints;
  double track_length_m = 0.0;
  double depth_min_m = 0.0;  ///< the sonar's, local down
  double depth_max_m = 0.0;
  /// The area in plan swept by the fans of every placed frame (a grid of ~500 cells a side).
  double coverage_area_m2 = 0.0;

  static constexpr std::size_t kMaxFootprints = 200;
};

SurveyPlan surveyPlan(const std::vector<PosedFrame>& frames, const SonarModel& sonar);

}  // namespace sonarcarve
