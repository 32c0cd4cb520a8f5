#include "io/rosbag/bag_navigation.h"

#include <algorithm>
#include <map>

#include "common/error.h"

namespace sonarcarve {
namespace {

Eigen::Isometry3d isometry(const Eigen::Vector3d& t, const Eigen::Quaterniond& q) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = q.normalized().toRotationMatrix();
  pose.translation() = t;
  return pose;
}

}  // namespace

BagNavigation bagNavigation(std::vector<TimedPose> poses, const std::string& source,
                            const std::string& topic) {
  if (poses.empty()) {
    throw Error(source, "topic " + topic, "no readable pose: expected navigation messages");
  }
  std::stable_sort(poses.begin(), poses.end(),
                   [](const TimedPose& a, const TimedPose& b) { return a.time_s < b.time_s; });
  const RosPoseMsg& first = poses.front().pose;
  const std::string body = first.child_frame_id.empty() ? "base_link" : first.child_frame_id;
  const RosFrameConventions conventions =
      rosFrameConventions(first.header.frame_id, first.child_frame_id);
  std::vector<NavSample> samples;
  std::size_t duplicates = 0;
  for (const TimedPose& p : poses) {
    if (!samples.empty() && p.time_s <= samples.back().time_s) {
      ++duplicates;
      continue;
    }
    const Eigen::Isometry3d T =
        ourWorldVehicle(isometry(p.pose.position, p.pose.orientation), conventions);
    NavSample s;
    s.time_s = p.time_s;
    s.position_m = T.translation();
    s.q_world_vehicle = Eigen::Quaterniond(T.linear()).normalized();
    samples.push_back(s);
  }
  return {NavTrack(std::move(samples)), conventions, body, duplicates, topic, ""};
}

std::optional<Mounting> bagMounting(const std::vector<RosTransformMsg>& transforms,
                                    const std::string& body_frame, bool body_frd,
                                    const std::string& sonar_frame, SonarAxes axes) {
  std::map<std::string, const RosTransformMsg*> parent_of;  // child -> transform
  for (const RosTransformMsg& t : transforms) {
    parent_of.try_emplace(t.child_frame_id, &t);
  }
  // Walk up from the sonar to the body; a chain longer than the transforms is a loop.
  Eigen::Isometry3d T_body_sonar = Eigen::Isometry3d::Identity();
  std::string frame = sonar_frame;
  for (std::size_t steps = 0; frame != body_frame; ++steps) {
    const auto it = parent_of.find(frame);
    if (it == parent_of.end() || steps > transforms.size()) {
      return std::nullopt;
    }
    T_body_sonar = isometry(it->second->translation, it->second->rotation) * T_body_sonar;
    frame = it->second->header.frame_id;
  }
  const Eigen::Isometry3d T = ourVehicleSonar(T_body_sonar, body_frd, axes);
  Mounting mounting;
  mounting.translation_m = T.translation();
  mounting.rpy = rollPitchYawFromQuaternion(Eigen::Quaterniond(T.linear()));
  return mounting;
}

}  // namespace sonarcarve
