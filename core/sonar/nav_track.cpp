#include "sonar/nav_track.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/error.h"

namespace sonarcarve {
namespace {
std::string samplePlace(std::size_t i) {
  return "sample " + std::to_string(i);
}
}  // namespace

NavTrack::NavTrack(std::vector<NavSample> samples) : samples_(std::move(samples)) {
  if (samples_.empty()) {
    throw Error("navigation", "", "expected at least one navigation sample");
  }
  for (std::size_t i = 0; i < samples_.size(); ++i) {
    NavSample& s = samples_[i];
    if (!std::isfinite(s.time_s) || !s.position_m.allFinite() ||
        !s.q_world_vehicle.coeffs().allFinite()) {
      throw Error("navigation", samplePlace(i), "expected finite time, position and attitude");
    }
    if (s.q_world_vehicle.norm() < 1e-9) {
      throw Error("navigation", samplePlace(i), "attitude quaternion has zero length");
    }
    s.q_world_vehicle.normalize();
    if (i > 0 && !(s.time_s > samples_[i - 1].time_s)) {
      throw Error("navigation", samplePlace(i), "times must strictly increase");
    }
  }
}

Eigen::Isometry3d NavTrack::T_world_vehicle(double time_s) const {
  if (!covers(time_s)) {
    throw Error("navigation", "t = " + std::to_string(time_s) + " s",
                "time outside the navigation track [" + std::to_string(startTime()) + ", " +
                    std::to_string(endTime()) + "] s");
  }
  // First sample at or after the time; interpolate from the one before it.
  const auto after = std::lower_bound(samples_.begin(), samples_.end(), time_s,
                                      [](const NavSample& s, double t) { return s.time_s < t; });
  if (after->time_s == time_s || after == samples_.begin()) {
    return after->T_world_vehicle();
  }
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  const NavSample& a = *(after - 1);
  const NavSample& b = *after;
  const double u = (time_s - a.time_s) / (b.time_s - a.time_s);
  pose.linear() = a.q_world_vehicle.slerp(u, b.q_world_vehicle).toRotationMatrix();
  pose.translation() = (1.0 - u) * a.position_m + u * b.position_m;
  return pose;
}

Eigen::Isometry3d NavTrack::T_world_sonar(double time_s,
                                          const Eigen::Isometry3d& T_vehicle_sonar) const {
  return T_world_vehicle(time_s) * T_vehicle_sonar;
}

}  // namespace sonarcarve
