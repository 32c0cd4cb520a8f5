// ROS frame conventions and ours (docs/conventions.md, docs/formats.md "ROS 2 bags").
// ROS (REP-103): world East-North-Up, body Forward-Left-Up; marine robots often use NED and
// FRD instead and say so in the frame name (REP-105 practice: "map_ned", "base_link_frd").
// Ours: world North-East-Down, vehicle and sonar Forward-Right-Down. The sonar frame of
// ProjectedSonarImage is the message's (io/rosbag/bag_options.h, SonarAxes).
#pragma once

#include <Eigen/Geometry>
#include <string>

#include "io/rosbag/bag_options.h"

namespace sonarcarve {

/// Which conventions a pose's frames follow, judged by their names.
struct RosFrameConventions {
  bool world_ned = false;  ///< false: ENU
  bool body_frd = false;   ///< false: FLU
};
/// World NED if `world_frame` ends in "_ned"; body FRD if `body_frame` ends in "_frd" or
/// "_ned", or, when the body is not named (PoseStamped), if the world is NED.
RosFrameConventions rosFrameConventions(const std::string& world_frame,
                                        const std::string& body_frame);
/// The conventions in words, for `info`: "world ENU, body FLU (REP-103)".
std::string describe(const RosFrameConventions& conventions);

/// A ROS pose of a body in a world (their conventions given) as our T_world_vehicle (NED, FRD),
/// and back (the conversion is its own inverse in form).
Eigen::Isometry3d ourWorldVehicle(const Eigen::Isometry3d& T_rosworld_rosbody,
                                  const RosFrameConventions& conventions);
Eigen::Isometry3d rosWorldBody(const Eigen::Isometry3d& T_world_vehicle,
                               const RosFrameConventions& conventions);

/// R_msg_ours: rotates a vector of our sonar frame (FRD, x along the boresight) into the
/// message's sonar frame for `axes` (ZForward, XForward or Frd; not Auto).
Eigen::Matrix3d rosSonarAxes(SonarAxes axes);
/// The mounting T_vehicle_sonar (ours) from the ROS transform of the message's sonar frame in
/// the body frame.
Eigen::Isometry3d ourVehicleSonar(const Eigen::Isometry3d& T_rosbody_rossonar, bool body_frd,
                                  SonarAxes axes);
Eigen::Isometry3d rosBodySonar(const Eigen::Isometry3d& T_vehicle_sonar, bool body_frd,
                               SonarAxes axes);

/// Bearing (ours: positive to starboard) of a beam direction given in the message's frame.
double bearingOfBeamDirection(const Eigen::Vector3d& direction, SonarAxes axes);
/// The beam direction (unit, elevation 0) of a bearing, in the message's frame.
Eigen::Vector3d beamDirectionOfBearing(double bearing_rad, SonarAxes axes);

}  // namespace sonarcarve
