#include "io/mission_summary.h"

namespace sonarcarve {

MissionSummary summarize(const Mission& mission, bool check_frames) {
  MissionSummary s;
  s.name = mission.name;
  s.frame_count = mission.frames.size();
  if (!mission.frames.empty()) {
    s.first_frame_time_s = mission.frames.front().time_s;
    s.last_frame_time_s = mission.frames.back().time_s;
    s.duration_s = s.last_frame_time_s - s.first_frame_time_s;
  }
  const auto& samples = mission.nav.samples();
  s.nav_samples = samples.size();
  s.nav_start_s = mission.nav.startTime();
  s.nav_end_s = mission.nav.endTime();
  s.nav_min_m = s.nav_max_m = samples.front().position_m;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    s.nav_min_m = s.nav_min_m.cwiseMin(samples[i].position_m);
    s.nav_max_m = s.nav_max_m.cwiseMax(samples[i].position_m);
    if (i > 0) {
      s.nav_path_length_m += (samples[i].position_m - samples[i - 1].position_m).norm();
    }
  }
  for (std::size_t i = 0; i < mission.frames.size(); ++i) {
    if (!mission.nav.covers(mission.frames[i].time_s)) {
      s.frames_outside_nav.push_back(i);
    }
  }
  if (check_frames) {
    s.frame_problems = checkFrames(mission);
  }
  return s;
}

}  // namespace sonarcarve
