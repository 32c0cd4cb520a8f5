// The survey's plan for the report (pipeline/report_html.h), as inline SVG: the area the fans
// swept (pale), the map's surface points, the track with its start and end, a north arrow and a
// scale bar; north up.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "pipeline/survey_plan.h"

namespace sonarcarve {

/// An <svg> element `width_px` wide; empty when the plan has no track. `points`: the map's
/// surface points (local NED), at most kMaxPlanPoints of them drawn, evenly picked.
std::string trackPlanSvg(const SurveyPlan& plan, const std::vector<Eigen::Vector3f>& points,
                         int width_px = 560);

inline constexpr std::size_t kMaxPlanPoints = 4000;

}  // namespace sonarcarve
