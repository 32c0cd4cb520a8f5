// Writing a mission as a ROS 2 bag: sonar frames as marine_acoustic_msgs/ProjectedSonarImage,
// the navigation as nav_msgs/Odometry (world ENU "map", body FLU "base_link", REP-103; local
// to the mission origin), optionally its positions as sensor_msgs/NavSatFix too and its origin
// as geographic_msgs/GeoPointStamped, and the
// mounting as one tf2_msgs/TFMessage on /tf_static. For tests and for `simulate --format`:
// a bag of a simulated mission, with its ground truth beside it, read back by our reader
// (io/rosbag/ros_bag.h) or by ROS tools. MCAP files are written without a summary section (readers
// then scan the data section, as after a crash); SQLite3 files with the Humble-era tables.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "common/enum_names.h"
#include "io/mission/mission.h"
#include "io/rosbag/bag_options.h"
#include "io/rosbag/ros_messages.h"

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
  /// Not empty: the positions also as sensor_msgs/NavSatFix on this topic (WGS84 latitude and
  /// longitude of the world position on the mission's grid, by PROJ; altitude = -down), and the
  /// Odometry's attitude from true north (grid north turned back by the grid convergence), as
  /// a vehicle's fix and INS give them. Needs a mission with a CRS.
  std::string fix_topic;
  /// Not empty: the mission origin as a geographic_msgs/GeoPointStamped on this topic (WGS84,
  /// altitude = -down) and, without fix_topic, the Odometry local to it in a frame aligned with
  /// true north (turned from grid north by the convergence at the origin), as a vehicle whose
  /// odometry has that point as its datum writes it. Needs a mission with a CRS.
  std::string origin_topic;
  std::string sonar_frame = "sonar";
  std::size_t chunk_bytes = std::size_t{4} << 20;
};

struct BagWriteReport {
  std::size_t frames = 0;
  std::size_t poses = 0;
};

/// A topic of a bag to write: its type's name and definition (ros2msg text, for MCAP schemas).
/// An empty type writes an MCAP channel without a schema.
struct BagTopicSpec {
  std::string name;
  std::string type;
  std::string definition;
};

/// A message to write: its topic (index into the topics), receive time and CDR bytes.
struct BagMessageSpec {
  std::size_t topic = 0;
  std::int64_t receive_ns = 0;
  std::vector<std::uint8_t> data;
};

/// Writes `messages` of `topics`, sorted by receive time, as an MCAP file (chunked as `format`
/// says) or a .db3 file: the storage under writeRosBag, for any message type (tests write raw
/// Oculus pings with it). Throws Error on a time before 0 or a file that cannot be written.
void writeBagMessages(const std::filesystem::path& out, BagFormat format,
                      const std::vector<BagTopicSpec>& topics, std::vector<BagMessageSpec> messages,
                      std::size_t chunk_bytes = std::size_t{4} << 20);

/// Writes every frame, navigation sample and the mounting of `mission` to `out` (atomically:
/// a temporary file renamed). Throws Error naming `out` or the frame on failure, and for
/// times before 0 (a bag's receive times are unsigned).
BagWriteReport writeRosBag(const Mission& mission, const std::filesystem::path& out,
                           const BagWriteOptions& options);

}  // namespace sonarcarve
