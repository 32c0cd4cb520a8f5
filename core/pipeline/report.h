// The report stage: report.json of a reconstruction (docs/formats.md): the mission (its name,
// sonar, frames, track and coverage), what ran and with which settings (every parameter, in
// words), what it produced, how fast, and, for a simulated mission that carries its
// ground truth (ground_truth.ply, visible_points.ply), the accuracy of the surface points and
// of the mesh.
#pragma once

#include <string>
#include <vector>

#include "pipeline/reconstruction.h"
#include "pipeline/survey_plan.h"

namespace sonarcarve {

/// The report as indented JSON text; the evaluation runs on `pool`. `sonar` is the sonar as
/// carving saw it, `survey` the run's track and fans in plan.
std::string reconstructionReport(const Mission& mission, const SonarModel& sonar,
                                 const ReconstructionParams& params,
                                 const ReconstructionResult& result, const SurveyPlan& survey,
                                 ThreadPool& pool);

}  // namespace sonarcarve
