// Writing a mission as a ROS 2 bag: sonar frames as marine_acoustic_msgs/ProjectedSonarImage,
// the navigation as nav_msgs/Odometry (world ENU "map", body FLU "base_link", REP-103) and the
// mounting as one tf2_msgs/TFMessage on /tf_static. For tests and for `simulate --format`:
// a bag of a simulated mission, with its ground truth beside it, read back by our reader
// (io/ros_bag.h) or by ROS tools. MCAP files are written without a summary section (readers
// then scan the data section, as after a crash); SQLite3 files with the Humble-era tables.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>

#include "common/enum_names.h"
#include "io/bag_options.h"
#include "io/mission.h"
#include "io/ros_messages.h"

namespace sonarcarve {

/// mcap: zstd chunks (as rosbag2 writes by default); mcap-lz4, mcap-none: other chunks;
/// mcap-unchunked: messages in the data section; db3: rosbag2's SQLite3 storage.
enum class BagFormat { Mcap, McapLz4, McapNone, McapUnchunked, Db3 };
inline constexpr std::array<EnumName<BagFormat>, 5> kBagFormatNames{{
    {BagFormat::Mcap, "mcap"},
    {BagFormat::McapLz4, "mcap-lz4"},
    {BagFormat::McapNone, "mcap-none"},
    {BagFormat::McapUnchunked, "mcap-unchunked"},
    {BagFormat::Db3, "db3"},
}};
constexpr const auto& enumNamesOf(BagFormat) {
  return kBagFormatNames;
}

struct BagWriteOptions {
  BagFormat format = BagFormat::Mcap;
  SonarAxes axes = SonarAxes::ZForward;  ///< of the beam directions written (not Auto)
  ImageLayout layout = ImageLayout::RangeMajor;
  /// Sample type; default: uint16 when a frame holds whole counts 0..65535, else float32.
  std::optional<SonarDtype> dtype;
  /// Receive time = header stamp + this (for the sonar messages).
  double receive_delay_s = 0.0;
  std::string sonar_topic = "/sonar/image";
  std::string nav_topic = "/odometry";
  std::string sonar_frame = "sonar";
  std::size_t chunk_bytes = std::size_t{4} << 20;
};

struct BagWriteReport {
  std::size_t frames = 0;
  std::size_t poses = 0;
};

/// Writes every frame, navigation sample and the mounting of `mission` to `out` (atomically:
/// a temporary file renamed). Throws Error naming `out` or the frame on failure, and for
/// times before 0 (a bag's receive times are unsigned).
BagWriteReport writeRosBag(const Mission& mission, const std::filesystem::path& out,
                           const BagWriteOptions& options);

}  // namespace sonarcarve
