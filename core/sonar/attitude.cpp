#include "sonar/attitude.h"

#include <algorithm>
#include <cmath>

namespace sonarcarve {

Eigen::Quaterniond quaternionFromRollPitchYaw(const RollPitchYaw& rpy) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(rpy.yaw_rad, Eigen::Vector3d::UnitZ()) *
                            Eigen::AngleAxisd(rpy.pitch_rad, Eigen::Vector3d::UnitY()) *
                            Eigen::AngleAxisd(rpy.roll_rad, Eigen::Vector3d::UnitX()));
}

RollPitchYaw rollPitchYawFromQuaternion(const Eigen::Quaterniond& q) {
  const Eigen::Matrix3d r = q.normalized().toRotationMatrix();
  RollPitchYaw rpy;
  rpy.pitch_rad = std::asin(std::clamp(-r(2, 0), -1.0, 1.0));
  rpy.roll_rad = std::atan2(r(2, 1), r(2, 2));
  rpy.yaw_rad = std::atan2(r(1, 0), r(0, 0));
  return rpy;
}

Eigen::Isometry3d makeTransform(const Eigen::Vector3d& translation_m, const RollPitchYaw& rpy) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = quaternionFromRollPitchYaw(rpy).toRotationMatrix();
  t.translation() = translation_m;
  return t;
}

}  // namespace sonarcarve
