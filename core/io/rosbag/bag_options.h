// How to read a ROS 2 bag (docs/formats.md, "ROS 2 bags"): which topics, which axis
// convention for the sonar's beam directions, which layout for the image data, and which
// clock. The defaults follow the message definitions; `info` prints what was assumed.
#pragma once

#include <array>
#include <string>

#include "common/enum_names.h"

namespace sonarcarve {

/// The sonar frame of ProjectedSonarImage.beam_directions. ZForward: the message comment's
/// (Z forward along the fan's centre, X up, so Y to starboard); XForward: REP-103's body frame
/// as some simulators write it (X forward, Y to port, Z up); Auto: ZForward if the directions'
/// Z components outweigh their X components, else XForward. Frd: X forward, Y starboard, Z
/// down (our sonar frame, and the NED frame of the older acoustic_msgs/SonarImage).
enum class SonarAxes { Auto, ZForward, XForward, Frd };
inline constexpr std::array<EnumName<SonarAxes>, 4> kSonarAxesNames{{
    {SonarAxes::Auto, "auto"},
    {SonarAxes::ZForward, "z-forward"},
    {SonarAxes::XForward, "x-forward"},
    {SonarAxes::Frd, "frd"},
}};
constexpr const auto& enumNamesOf(SonarAxes) {
  return kSonarAxesNames;
}

/// The order of SonarImageData.data. RangeMajor: one row per range, data[r * beams + b] (the
/// reference drivers and sonar_image_proc); BeamMajor: one run per beam, data[b * ranges + r].
enum class ImageLayout { RangeMajor, BeamMajor };
inline constexpr std::array<EnumName<ImageLayout>, 2> kImageLayoutNames{{
    {ImageLayout::RangeMajor, "range-major"},
    {ImageLayout::BeamMajor, "beam-major"},
}};
constexpr const auto& enumNamesOf(ImageLayout) {
  return kImageLayoutNames;
}

/// Which time a message gets: its header stamp (when the ping was sent, by the message
/// definition) or the time the recorder received it.
enum class BagTime { Header, Receive };
inline constexpr std::array<EnumName<BagTime>, 2> kBagTimeNames{{
    {BagTime::Header, "header"},
    {BagTime::Receive, "receive"},
}};
constexpr const auto& enumNamesOf(BagTime) {
  return kBagTimeNames;
}

struct BagOptions {
  std::string sonar_topic;  ///< empty: the only sonar image or raw Oculus ping topic
  std::string nav_topic;    ///< empty: the only Odometry / PoseStamped topic
  std::string fix_topic;    ///< empty: the only sensor_msgs/NavSatFix topic, if any
  /// empty: the only geographic_msgs/GeoPoint or GeoPointStamped topic, if any: the mission
  /// origin
  std::string origin_topic;
  SonarAxes axes = SonarAxes::Auto;
  ImageLayout layout = ImageLayout::RangeMajor;
  BagTime time = BagTime::Header;
};

}  // namespace sonarcarve
