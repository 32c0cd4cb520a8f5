// ROS 2 bags, whatever their storage: a list of topics (name, type, message count) and of
// messages (topic, receive time, where the payload is), read from
//   - MCAP files (io/rosbag/mcap_bag.cpp; uncompressed, lz4 or zstd chunks, no summary needed),
//   - SQLite3 files (rosbag2's .db3: tables topics and messages),
//   - a bag folder (metadata.yaml beside its storage files; every file is read, in order).
// Opening indexes the messages; payload() reads one on demand (thread safe). Messages or
// records that are corrupt are reported in problems() and left out; a file with nothing
// readable throws Error naming the file, the place and what was expected.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace sonarcarve {

struct BagTopic {
  std::string name;
  std::string type;      ///< as stored ("marine_acoustic_msgs/msg/ProjectedSonarImage")
  std::string encoding;  ///< "cdr"
  std::size_t messages = 0;
  /// The message definition (an MCAP schema's ros2msg text); "" when the bag has none.
  std::string definition;
};

struct BagMessage {
  std::size_t topic = 0;        ///< into topics()
  std::int64_t receive_ns = 0;  ///< the bag's time (MCAP log_time, SQLite timestamp)
  std::size_t file = 0;         ///< storage file of a bag folder
  std::uint64_t locator = 0;    ///< where the storage finds it (record or row)
  std::string place;            ///< for messages: "message 12, byte 3456"
};

class RosBag {
 public:
  virtual ~RosBag() = default;
  /// The path opened (file or folder).
  virtual const std::filesystem::path& path() const = 0;
  /// "MCAP (zstd chunks)", "SQLite3", "bag folder of 2 MCAP files" ...
  virtual std::string storage() const = 0;
  virtual const std::vector<BagTopic>& topics() const = 0;
  /// Every message, in storage order.
  virtual const std::vector<BagMessage>& messages() const = 0;
  virtual const std::vector<std::string>& problems() const = 0;
  /// The CDR bytes of a message. Throws Error naming the file and the message.
  virtual std::vector<std::uint8_t> payload(const BagMessage& message) const = 0;
};

/// True if `path` is an MCAP file (magic), a SQLite3 file with a `messages` table, or a folder
/// with a metadata.yaml. Never throws.
bool looksLikeRosBag(const std::filesystem::path& path);

/// Opens and indexes a bag file or folder. Throws Error on an unreadable bag.
std::unique_ptr<RosBag> openRosBag(const std::filesystem::path& path);

/// The storage readers behind openRosBag (also used by the fuzz targets).
std::unique_ptr<RosBag> openMcapBag(const std::filesystem::path& path);
std::unique_ptr<RosBag> openSqliteBag(const std::filesystem::path& path);

}  // namespace sonarcarve
