#include "io/mission/mission_summary.h"

namespace sonarcarve {

MissionSummary summarizeFrames(std::string name, const std::vector<double>& frame_times_s,
                               const NavTrack& nav) {
  MissionSummary s;
  s.name = std::move(name);
  s.frame_count = frame_times_s.size();
  if (!frame_times_s.empty()) {
    s.first_frame_time_s = frame_times_s.front();
    s.last_frame_time_s = frame_times_s.back();
    s.duration_s = s.last_frame_time_s - s.first_frame_time_s;
  }
  const auto& samples = nav.samples();
  s.nav_samples = samples.size();
  s.nav_start_s = nav.startTime();
  s.nav_end_s = nav.endTime();
  s.nav_min_m = s.nav_max_m = samples.front().position_m;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    s.nav_min_m = s.nav_min_m.cwiseMin(samples[i].position_m);
    s.nav_max_m = s.nav_max_m.cwiseMax(samples[i].position_m);
    if (i > 0) {
      s.nav_path_length_m += (samples[i].position_m - samples[i - 1].position_m).norm();
    }
  }
  for (std::size_t i = 0; i < frame_times_s.size(); ++i) {
    if (!nav.covers(frame_times_s[i])) {
      s.frames_outside_nav.push_back(i);
    }
  }
  return s;
}

MissionSummary summarize(const Mission& mission, bool check_frames) {
  std::vector<double> times;
  times.reserve(mission.frames.size());
  for (const FrameRecord& f : mission.frames) {
    times.push_back(f.time_s);
  }
  MissionSummary s = summarizeFrames(mission.name, times, mission.nav);
  if (check_frames) {
    s.frame_problems = checkFrames(mission);
  }
  return s;
}

}  // namespace sonarcarve
