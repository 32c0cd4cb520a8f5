#include "io/rosbag/ros_frames.h"

#include <cmath>

namespace sonarcarve {
namespace {

bool endsWith(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// ENU <-> NED (swap x and y, negate z) and FLU <-> FRD (negate y and z); each its own inverse.
Eigen::Matrix3d worldSwap(bool ned) {
  Eigen::Matrix3d m;
  m << 0, 1, 0, 1, 0, 0, 0, 0, -1;
  return ned ? Eigen::Matrix3d::Identity() : m;
}

Eigen::Matrix3d bodySwap(bool frd) {
  return frd ? Eigen::Matrix3d::Identity()
             : Eigen::Vector3d(1, -1, -1).asDiagonal().toDenseMatrix();
}

Eigen::Isometry3d sandwich(const Eigen::Matrix3d& left, const Eigen::Isometry3d& pose,
                           const Eigen::Matrix3d& right) {
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.linear() = left * pose.linear() * right;
  out.translation() = left * pose.translation();
  return out;
}

}  // namespace

RosFrameConventions rosFrameConventions(const std::string& world_frame,
                                        const std::string& body_frame) {
  RosFrameConventions c;
  c.world_ned = endsWith(world_frame, "_ned");
  c.body_frd = body_frame.empty() ? c.world_ned
                                  : endsWith(body_frame, "_frd") || endsWith(body_frame, "_ned");
  return c;
}

std::string describe(const RosFrameConventions& c) {
  return std::string("world ") + (c.world_ned ? "NED" : "ENU") + ", body " +
         (c.body_frd ? "FRD" : "FLU") +
         (!c.world_ned && !c.body_frd ? " (REP-103)" : " (frame names ending in _ned/_frd)");
}

Eigen::Isometry3d ourWorldVehicle(const Eigen::Isometry3d& T_rosworld_rosbody,
                                  const RosFrameConventions& c) {
  return sandwich(worldSwap(c.world_ned), T_rosworld_rosbody, bodySwap(c.body_frd));
}

Eigen::Isometry3d rosWorldBody(const Eigen::Isometry3d& T_world_vehicle,
                               const RosFrameConventions& c) {
  return sandwich(worldSwap(c.world_ned), T_world_vehicle, bodySwap(c.body_frd));
}

Eigen::Matrix3d rosSonarAxes(SonarAxes axes) {
  if (axes == SonarAxes::XForward) {
    return bodySwap(false);
  }
  if (axes == SonarAxes::Frd) {
    return Eigen::Matrix3d::Identity();
  }
  // Our x (boresight) -> message Z, our y (starboard) -> message Y, our z (down) -> -X (X up).
  Eigen::Matrix3d m;
  m << 0, 0, -1, 0, 1, 0, 1, 0, 0;
  return m;
}

Eigen::Isometry3d ourVehicleSonar(const Eigen::Isometry3d& T_rosbody_rossonar, bool body_frd,
                                  SonarAxes axes) {
  return sandwich(bodySwap(body_frd), T_rosbody_rossonar, rosSonarAxes(axes));
}

Eigen::Isometry3d rosBodySonar(const Eigen::Isometry3d& T_vehicle_sonar, bool body_frd,
                               SonarAxes axes) {
  return sandwich(bodySwap(body_frd), T_vehicle_sonar, rosSonarAxes(axes).transpose());
}

double bearingOfBeamDirection(const Eigen::Vector3d& direction, SonarAxes axes) {
  const Eigen::Vector3d ours = rosSonarAxes(axes).transpose() * direction;
  return std::atan2(ours.y(), ours.x());
}

Eigen::Vector3d beamDirectionOfBearing(double bearing_rad, SonarAxes axes) {
  return rosSonarAxes(axes) * Eigen::Vector3d(std::cos(bearing_rad), std::sin(bearing_rad), 0.0);
}

}  // namespace sonarcarve
