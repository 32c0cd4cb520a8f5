#include "pipeline/report_page.h"

#include "common/error.h"
#include "io/files/atomic_file.h"
#include "io/files/png_codec.h"
#include "pipeline/map_pictures.h"
#include "pipeline/report_html.h"
#include "pipeline/track_plan_svg.h"
#include "sonar/fan_image.h"

namespace sonarcarve {
namespace {

constexpr int kFanWidth = 440;

// The middle carved frame, raw and as carving read it, in the sonar's counts and one
// intensity window (the raw frame's).
void addFans(const RunContext& run, ReportPage& page) {
  const std::vector<PosedFrame>& used = run.carved.used.empty() ? run.posed : run.carved.used;
  if (used.empty() || !run.frames) {
    page.fans_missing = "No frame was carved, so there is no frame to show.";
    return;
  }
  const std::size_t index = used[used.size() / 2].index;
  try {
    const IntensityScale& scale = run.mission.sonar.intensityScale();
    const cv::Mat raw = scale.powerToCounts(loadFrame(run.mission, index).image);
    const cv::Mat denoised = scale.powerToCounts(run.frames->load(index).image);
    const DisplayWindow window = DisplayWindow::fromPercentiles(raw);
    const std::string frame = "Frame " + std::to_string(index) + " of the mission";
    page.fans.push_back({"As recorded",
                         frame + ", in true geometry: the sonar at the bottom, range rings every "
                                 "metre, brighter for stronger echoes.",
                         encodePng(fanPicture(raw, run.mission.sonar, window, kFanWidth), "fan")});
    page.fans.push_back(
        {"As carved",
         frame + " after denoising (" + run.result.detector +
             " detector), in the same brightness scale: what the map was built from.",
         encodePng(fanPicture(denoised, run.mission.sonar, window, kFanWidth), "denoised fan")});
  } catch (const Error& e) {
    page.fans.clear();
    page.fans_missing = std::string("The sample frame could not be drawn: ") + e.what();
  }
}

void addMapViews(const std::vector<Eigen::Vector3f>& points, double voxel_m, ReportPage& page) {
  for (MapPicture& view : mapPictures(points, voxel_m)) {
    page.map_views.push_back({view.title,
                              "Surface points coloured by height; the scale bar is in metres.",
                              encodePng(view.image, view.title)});
  }
}

}  // namespace

void writeReportPage(const RunContext& run, const std::filesystem::path& folder,
                     const std::vector<RunManifestFile>& deliverables) {
  ReportPage page;
  page.report_json = run.result.report;
  const std::vector<Eigen::Vector3f> points = positionsOf(run.result.surface);
  page.plan_svg = trackPlanSvg(run.survey, points);
  addMapViews(points, run.params.carve.voxel_size_m, page);
  addFans(run, page);
  page.deliverables = deliverables;
  writeFileAtomically(folder / "report.html", reportHtml(page));
}

}  // namespace sonarcarve
