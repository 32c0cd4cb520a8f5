// Oculus pings carried raw in ROS 2 bags (docs/formats.md, "Raw Oculus pings in bags"): a
// driver that logs the sonar's own network messages (apl_msgs/msg/RawData on `raw_data`, a
// driver's ping message with a `uint8[] data` field, std_msgs/msg/UInt8MultiArray, ...) is
// read by content, whatever the type's name: a message holds an Oculus message when one of its
// uint8[] fields starts with the Oculus header magic 0x4f53. The bytes go through our Oculus
// decoder (io/oculus/oculus_message.h); the frame's time is the message's std_msgs/Header stamp
// when it starts with one (by its MCAP schema, else by its bytes), else the bag's receive time.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "io/rosbag/bag_options.h"
#include "io/rosbag/ros_bag.h"
#include "io/rosbag/ros_messages.h"
#include "sonar/sonar_model.h"

namespace sonarcarve {

/// Where an Oculus message lies in a CDR payload.
struct OculusField {
  std::size_t offset = 0;  ///< of its first byte (the magic) in the payload
  std::size_t size = 0;    ///< bytes of the uint8[] field that holds it
};

/// The first uint8[] field of a CDR payload (a u32 count at a 4-byte boundary of the CDR body,
/// then the bytes) of at least an Oculus header's 16 bytes that start with the Oculus magic
/// (53 4F). Never throws.
std::optional<OculusField> findOculusField(std::span<const std::uint8_t> cdr);

/// True if one of the first 16 messages of `topic` holds a whole Oculus message (its header's
/// size within the field), whatever the type's name.
bool isOculusTopic(const RosBag& bag, std::size_t topic);

/// A frame of a bag: its time and the message that holds it.
struct BagFrameRef {
  double time_s = 0.0;
  std::size_t message = 0;  ///< into RosBag::messages()
};

struct BagOculusFrames {
  std::optional<SonarModel> sonar;  ///< of the first readable ping
  std::vector<BagFrameRef> frames;  ///< pings of that geometry, in time order
  std::string frame_id;             ///< of the first ping's message header ("" without one)
  std::vector<std::string> notes;   ///< what was assumed or skipped, for `info`
};

/// Indexes the pings of an Oculus topic: each is decoded (without its image) and checked;
/// corrupt ones, and pings of another geometry than the first, are reported in `problems`
/// (naming the bag, the topic and the message) and left out. Throws Error if none is left.
BagOculusFrames indexOculusFrames(const RosBag& bag, std::size_t topic, BagTime clock,
                                  double time_offset_s, std::optional<double> aperture_deg,
                                  std::vector<std::string>& problems);

/// The image of the ping in `cdr` (rows near to far, columns port to starboard, the counts as
/// sent). Throws Error naming `source` and `place` if it does not decode or is not of `sonar`'s
/// geometry.
cv::Mat bagOculusImage(std::span<const std::uint8_t> cdr, const SonarModel& sonar,
                       const std::string& source, const std::string& place);

}  // namespace sonarcarve
