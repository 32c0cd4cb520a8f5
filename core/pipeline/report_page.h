// report.html of a run (pipeline/report_html.h) from what the run left in its RunContext:
// report.json's text, the survey plan, the surface points drawn from three sides, and the
// middle frame of the run drawn as a fan before and after denoising.
#pragma once

#include <filesystem>
#include <vector>

#include "io/run/run_manifest.h"
#include "pipeline/run_context.h"

namespace sonarcarve {

/// Writes `folder`/report.html atomically; `deliverables` are the run's files written so far.
void writeReportPage(const RunContext& run, const std::filesystem::path& folder,
                     const std::vector<RunManifestFile>& deliverables);

}  // namespace sonarcarve
