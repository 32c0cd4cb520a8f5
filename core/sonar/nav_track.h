// NavTrack: the vehicle's timed positions and attitudes in the world frame (NED, metres),
// interpolated linearly in position and by slerp in attitude. With the sonar's mounting on
// the vehicle it gives T_world_sonar(t). A time outside the track is an error, never an
// extrapolation. Immutable after construction; safe to share between threads.
#pragma once

#include <Eigen/Geometry>
#include <vector>

namespace sonarcarve {

struct NavSample {
  double time_s = 0.0;
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();  ///< vehicle origin, world NED
  Eigen::Quaterniond q_world_vehicle = Eigen::Quaterniond::Identity();

  /// The sample as a transform from the vehicle frame to the world.
  Eigen::Isometry3d T_world_vehicle() const {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = q_world_vehicle.toRotationMatrix();
    pose.translation() = position_m;
    return pose;
  }
};

class NavTrack {
 public:
  /// Samples must be non-empty, finite and strictly increasing in time (throws Error).
  explicit NavTrack(std::vector<NavSample> samples);

  const std::vector<NavSample>& samples() const { return samples_; }
  double startTime() const { return samples_.front().time_s; }
  double endTime() const { return samples_.back().time_s; }
  bool covers(double time_s) const { return time_s >= startTime() && time_s <= endTime(); }

  /// Vehicle pose at `time_s`; throws Error when the time lies outside the track.
  Eigen::Isometry3d T_world_vehicle(double time_s) const;
  /// Sonar pose at `time_s`, given the sonar's pose on the vehicle.
  Eigen::Isometry3d T_world_sonar(double time_s, const Eigen::Isometry3d& T_vehicle_sonar) const;

 private:
  std::vector<NavSample> samples_;
};

}  // namespace sonarcarve
