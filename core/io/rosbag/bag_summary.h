// What a ROS 2 bag holds, for `info` and for choosing topics (docs/formats.md, "ROS 2 bags"):
// each topic's kind to SonarCarve (by its type name; raw Oculus pings by their content,
// io/rosbag/bag_oculus.h) and one line per topic with its type and message count. A bag without a
// sonar topic is still summarised, so that `info` lists any valid bag.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "io/rosbag/ros_bag.h"
#include "io/rosbag/ros_messages.h"

namespace sonarcarve {

class BagTopicKinds {
 public:
  /// Looks at every topic's type, and at the first messages of the others for Oculus pings.
  explicit BagTopicKinds(const RosBag& bag);
  /// Sonar topics are sonar image messages and raw Oculus pings.
  bool is(std::size_t topic, RosMessageKind kind) const;
  bool oculus(std::size_t topic) const { return oculus_[topic]; }
  /// True if some topic is a sonar topic.
  bool anySonar() const;

 private:
  std::vector<RosMessageKind> by_type_;
  std::vector<bool> oculus_;
};

/// "storage MCAP (zstd chunks), N messages", then "topic NAME: TYPE, N messages" for each
/// topic (its encoding when not cdr; "Oculus sonar pings (raw)" for Oculus topics).
std::vector<std::string> bagTopicLines(const RosBag& bag, const BagTopicKinds& kinds);

}  // namespace sonarcarve
