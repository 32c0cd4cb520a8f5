#include "io/holoocean/holoocean_frames.h"

namespace sonarcarve {
namespace {

// The half turn about x between HoloOcean's z-up frames and our z-down ones; its own inverse.
const Eigen::Matrix3d& halfTurn() {
  static const Eigen::Matrix3d D = Eigen::Vector3d(1.0, -1.0, -1.0).asDiagonal();
  return D;
}

}  // namespace

Eigen::Isometry3d nedPoseFromHoloOcean(const Eigen::Matrix4d& T_holo) {
  const Eigen::Matrix3d& D = halfTurn();
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = D * T_holo.topLeftCorner<3, 3>() * D;
  pose.translation() = D * T_holo.topRightCorner<3, 1>();
  return pose;
}

Eigen::Matrix4d holoOceanPoseFromNed(const Eigen::Isometry3d& T_ned_sonar) {
  const Eigen::Matrix3d& D = halfTurn();
  Eigen::Matrix4d T = Eigen::Matrix4d::Identity();
  T.topLeftCorner<3, 3>() = D * T_ned_sonar.linear() * D;
  T.topRightCorner<3, 1>() = D * T_ned_sonar.translation();
  return T;
}

}  // namespace sonarcarve
