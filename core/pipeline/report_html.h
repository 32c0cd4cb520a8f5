// report.html, the survey report a client reads (docs/formats.md, "report.html"): the run's
// report.json in words and pictures, in one self-contained page (inline CSS, SVG and PNG as
// data: URLs; no script, nothing fetched). Every figure comes from report.json and sits in an
// element whose data-json attribute is its JSON pointer there ("/evaluation/fscore"), so that
// a reader (or a test) can check the page against the file. Whatever comes from the mission
// or the run is escaped (pipeline/html_text.h).
#pragma once

#include <string>
#include <vector>

#include "io/run/run_manifest.h"

namespace sonarcarve {

struct ReportPicture {
  std::string title;    ///< plain text
  std::string caption;  ///< plain text
  std::string png;      ///< the PNG's bytes
};

struct ReportPage {
  std::string report_json;                    ///< report.json's text
  std::string plan_svg;                       ///< the track plan (pipeline/track_plan_svg.h)
  std::vector<ReportPicture> map_views;       ///< the map from three sides
  std::vector<ReportPicture> fans;            ///< a frame before and after denoising
  std::string fans_missing;                   ///< why there are none, when there are none
  std::vector<RunManifestFile> deliverables;  ///< the run's files with their SHA-256
};

/// The page. Throws Error if report_json is not a JSON object.
std::string reportHtml(const ReportPage& page);

}  // namespace sonarcarve
