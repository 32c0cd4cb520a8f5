// Navigation and mounting from a ROS 2 bag (docs/formats.md, "ROS 2 bags"): the vehicle's
// poses (Odometry, PoseStamped, PoseWithCovarianceStamped) become a NavTrack in our world NED
// and vehicle FRD frames, the frames' names saying which ROS convention they follow
// (io/rosbag/ros_frames.h); the sonar's mounting comes from the transforms of /tf_static, chained
// from the vehicle's frame to the sonar messages' frame.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "io/rosbag/bag_options.h"
#include "io/rosbag/ros_frames.h"
#include "io/rosbag/ros_messages.h"
#include "sonar/mounting.h"
#include "sonar/nav_track.h"

namespace sonarcarve {

struct TimedPose {
  double time_s = 0.0;
  RosPoseMsg pose;
};

struct BagNavigation {
  NavTrack track;
  RosFrameConventions conventions;
  std::string body_frame;      ///< child_frame_id, or "base_link" for PoseStamped types
  std::size_t duplicates = 0;  ///< samples left out: their time did not increase
  std::string topic;           ///< the topic read, and what was assumed, for `info`
  std::string description;
};

/// The track of poses (sorted by time; repeated times keep the first). Throws Error naming
/// `source` and the topic if fewer than one pose is left.
BagNavigation bagNavigation(std::vector<TimedPose> poses, const std::string& source,
                            const std::string& topic);

/// The mounting of the frame `sonar_frame` on `body_frame`, chaining transforms (parent ->
/// child) from `transforms`; nothing if no chain joins them.
std::optional<Mounting> bagMounting(const std::vector<RosTransformMsg>& transforms,
                                    const std::string& body_frame, bool body_frd,
                                    const std::string& sonar_frame, SonarAxes axes);

}  // namespace sonarcarve
