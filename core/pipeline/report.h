// The report stage: report.json of a reconstruction (docs/formats.md): what ran and with
// which settings, what it produced, how fast, and, for a simulated mission that carries its
// ground truth (ground_truth.ply, visible_points.ply), the accuracy of the surface points and
// of the mesh.
#pragma once

#include <string>
#include <vector>

#include "pipeline/reconstruction.h"

namespace sonarcarve {

/// The report as indented JSON text; the evaluation runs on `pool`.
std::string reconstructionReport(const Mission& mission, const ReconstructionParams& params,
                                 const ReconstructionResult& result, ThreadPool& pool);

}  // namespace sonarcarve
