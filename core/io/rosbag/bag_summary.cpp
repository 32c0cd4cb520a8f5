#include "io/rosbag/bag_summary.h"

#include <algorithm>

#include "io/rosbag/bag_oculus.h"

namespace sonarcarve {

BagTopicKinds::BagTopicKinds(const RosBag& bag) {
  for (std::size_t t = 0; t < bag.topics().size(); ++t) {
    by_type_.push_back(rosMessageKind(bag.topics()[t].type));
    oculus_.push_back(isOculusTopic(bag, t));
  }
}

bool BagTopicKinds::is(std::size_t topic, RosMessageKind kind) const {
  return by_type_[topic] == kind || (kind == RosMessageKind::SonarImage && oculus_[topic]);
}

bool BagTopicKinds::anySonar() const {
  for (std::size_t t = 0; t < by_type_.size(); ++t) {
    if (is(t, RosMessageKind::SonarImage)) {
      return true;
    }
  }
  return false;
}

std::vector<std::string> bagTopicLines(const RosBag& bag, const BagTopicKinds& kinds) {
  std::vector<std::string> lines{"storage " + bag.storage() + ", " +
                                 std::to_string(bag.messages().size()) + " messages"};
  for (std::size_t k = 0; k < bag.topics().size(); ++k) {
    const BagTopic& t = bag.topics()[k];
    lines.push_back("topic " + t.name + ": " + (t.type.empty() ? "(no schema)" : t.type) + ", " +
                    std::to_string(t.messages) + " messages" +
                    (t.encoding == "cdr" ? "" : " (encoding " + t.encoding + ")") +
                    (kinds.oculus(k) ? ", Oculus sonar pings (raw)" : ""));
  }
  return lines;
}

}  // namespace sonarcarve
