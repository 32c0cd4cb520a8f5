// Attitude convention: roll, pitch, yaw (Tait-Bryan, Z-Y'-X'') of a body in the NED world:
//   R_world_body = Rz(yaw) * Ry(pitch) * Rx(roll).
// Positive yaw turns the bow to starboard (north -> east), positive pitch raises the bow,
// positive roll lowers the starboard side. Radians inside; degrees only in files and UI.
#pragma once

#include <Eigen/Geometry>

namespace sonarcarve {

struct RollPitchYaw {
  double roll_rad = 0.0;
  double pitch_rad = 0.0;
  double yaw_rad = 0.0;
};

Eigen::Quaterniond quaternionFromRollPitchYaw(const RollPitchYaw& rpy);
/// Inverse of quaternionFromRollPitchYaw, with pitch in [-pi/2, pi/2] and roll, yaw in (-pi, pi].
RollPitchYaw rollPitchYawFromQuaternion(const Eigen::Quaterniond& q);

/// A rigid transform from a translation and a roll/pitch/yaw attitude.
Eigen::Isometry3d makeTransform(const Eigen::Vector3d& translation_m, const RollPitchYaw& rpy);

}  // namespace sonarcarve
