// Oculus logs (message streams and ViewPoint recordings) opened in place: the pings of the
// log's main geometry are the frames, decoded on demand from the memory-mapped log, placed
// with the navigation CSV given beside the log (OpenOptions), or stationary at the origin
// without one (with a warning). The same choices as `import` (io/import.h), without copies.
#include "io/frame_source.h"
#include "io/import.h"
#include "io/oculus/oculus_log.h"

namespace sonarcarve {
namespace {

class OculusSource final : public FrameSource {
 public:
  OculusSource(std::shared_ptr<const OculusLog> log, OculusImportPlan plan)
      : log_(std::move(log)), plan_(std::move(plan)) {}

  std::string kind() const override { return log_->container(); }
  std::size_t size() const override { return plan_.pings.size(); }
  Frame load(std::size_t index) const override {
    Frame frame;
    frame.time_s = plan_.frame_times_s.at(index);
    frame.sonar_id = plan_.sonar.id();
    frame.image = log_->decode(plan_.pings.at(index)).image;
    return frame;
  }

 private:
  std::shared_ptr<const OculusLog> log_;
  OculusImportPlan plan_;
};

Mission openOculusLog(const std::filesystem::path& path, const OpenOptions& options) {
  auto log = std::make_shared<const OculusLog>(OculusLog::open(path));
  // Times and aperture go through the plan; navigation and mounting through the options.
  OculusImportPlan plan =
      planOculusImport(*log, options.time_offset_s, options.vertical_aperture_deg);
  Mission mission = recordingMission(path, plan.sonar, plan.frame_times_s, [&](std::size_t k) {
    return "ping " + std::to_string(plan.pings[k]);
  });
  mission.warnings = plan.warnings;
  for (const std::string& problem : log->problems()) {
    mission.warnings.push_back(problem + " (skipped)");
  }
  if (!log->skippedSummary().empty()) {
    mission.warnings.push_back(log->skippedSummary());
  }
  if (options.nav_csv.empty()) {
    mission.warnings.push_back(
        "no navigation given (--nav): the vehicle is stationary at the origin with zero "
        "attitude");
  }
  applyNavigationAndMounting(mission, options);
  mission.source = std::make_shared<const OculusSource>(std::move(log), std::move(plan));
  return mission;
}

[[maybe_unused]] const bool registered = registerFrameSourceReader(
    {"oculus", [](const std::filesystem::path& path) { return looksLikeOculusLog(path); },
     openOculusLog});

}  // namespace
}  // namespace sonarcarve
