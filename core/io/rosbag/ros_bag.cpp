#include "io/rosbag/ros_bag.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <fstream>
#include <map>

#include "common/error.h"
#include "common/input_limits.h"
#include "io/files/input_file.h"
#include "io/rosbag/mcap_format.h"

namespace sonarcarve {
namespace {

constexpr char kSqliteMagic[] = "SQLite format 3";  // and a NUL: 16 bytes
constexpr const char* kBagMetadata = "metadata.yaml";

enum class BagFileKind { None, Mcap, Sqlite };

BagFileKind bagFileKind(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    return BagFileKind::None;
  }
  std::ifstream in(path, std::ios::binary);
  std::array<char, 16> head{};
  in.read(head.data(), head.size());
  const auto got = static_cast<std::size_t>(in.gcount());
  if (got >= mcap::kMagic.size() && std::memcmp(head.data(), mcap::kMagic.data(), 8) == 0) {
    return BagFileKind::Mcap;
  }
  if (got == head.size() && std::memcmp(head.data(), kSqliteMagic, sizeof kSqliteMagic) == 0) {
    return BagFileKind::Sqlite;
  }
  return BagFileKind::None;
}

// A SQLite3 file is a bag if its schema names a `messages` table; read from the file's text
// (the schema is stored as SQL text), not by opening it, so that recognising never fails.
bool sqliteHasMessagesTable(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(1 << 16, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  return head.find("CREATE TABLE messages") != std::string::npos ||
         head.find("CREATE TABLE \"messages\"") != std::string::npos;
}

std::unique_ptr<RosBag> openBagFile(const std::filesystem::path& path) {
  requireRegularFile(path, "a bag storage file (.mcap or .db3)");
  switch (bagFileKind(path)) {
    case BagFileKind::Mcap:
      return openMcapBag(path);
    case BagFileKind::Sqlite:
      return openSqliteBag(path);
    case BagFileKind::None:
      break;
  }
  if (path.extension() == ".zstd" || path.extension() == ".lz4") {
    throw Error(path.string(), "",
                "a bag file compressed as a whole (rosbag2's compression_mode: file): "
                "decompress it first (zstd -d), then open the folder or the file");
  }
  throw Error(path.string(), bytePlace(0),
              "not a bag storage file (expected the MCAP magic or a SQLite3 header)");
}

// A bag folder: its storage files, one after another, seen as one bag. Topics with the same
// name and type in several files are one topic.
class FolderBag final : public RosBag {
 public:
  FolderBag(std::filesystem::path path, std::vector<std::unique_ptr<RosBag>> parts)
      : path_(std::move(path)), parts_(std::move(parts)) {
    std::map<std::pair<std::string, std::string>, std::size_t> merged;
    for (std::size_t f = 0; f < parts_.size(); ++f) {
      const RosBag& part = *parts_[f];
      std::vector<std::size_t> topic_map;
      for (const BagTopic& t : part.topics()) {
        const auto key = std::make_pair(t.name, t.type);
        const auto [it, added] = merged.try_emplace(key, topics_.size());
        if (added) {
          topics_.push_back({t.name, t.type, t.encoding, 0, t.definition});
        }
        topics_[it->second].messages += t.messages;
        topic_map.push_back(it->second);
      }
      for (const BagMessage& m : part.messages()) {
        BagMessage copy = m;
        copy.topic = topic_map.at(m.topic);
        copy.file = f;
        copy.place = part.path().filename().string() + ": " + m.place;
        messages_.push_back(std::move(copy));
      }
      problems_.insert(problems_.end(), part.problems().begin(), part.problems().end());
    }
  }

  const std::filesystem::path& path() const override { return path_; }
  std::string storage() const override {
    return "bag folder of " + std::to_string(parts_.size()) + " " + parts_.front()->storage() +
           " file" + (parts_.size() > 1 ? "s" : "");
  }
  const std::vector<BagTopic>& topics() const override { return topics_; }
  const std::vector<BagMessage>& messages() const override { return messages_; }
  const std::vector<std::string>& problems() const override { return problems_; }
  std::vector<std::uint8_t> payload(const BagMessage& message) const override {
    return parts_.at(message.file)->payload(message);
  }

 private:
  std::filesystem::path path_;
  std::vector<std::unique_ptr<RosBag>> parts_;
  std::vector<BagTopic> topics_;
  std::vector<BagMessage> messages_;
  std::vector<std::string> problems_;
};

// The storage files of a bag folder: metadata.yaml's relative_file_paths, or else every
// .mcap and .db3 file in it, in name order.
std::vector<std::filesystem::path> folderFiles(const std::filesystem::path& folder) {
  const std::filesystem::path metadata = folder / kBagMetadata;
  std::vector<std::filesystem::path> files;
  if (std::error_code ec; std::filesystem::exists(metadata, ec)) {
    requireInputSize(metadata, "rosbag2's metadata.yaml", kMaxYamlFileBytes);
  }
  try {
    const YAML::Node root = YAML::LoadFile(metadata.string());
    const YAML::Node paths = root["rosbag2_bagfile_information"]["relative_file_paths"];
    if (paths && paths.IsSequence()) {
      for (const YAML::Node& p : paths) {
        files.push_back(folder / p.as<std::string>());
      }
    }
  } catch (const YAML::Exception& e) {
    throw Error(metadata.string(), "line " + std::to_string(e.mark.line + 1),
                std::string(e.what()) + " (expected rosbag2's metadata.yaml)");
  }
  if (files.empty()) {
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
      const auto ext = entry.path().extension();
      if (ext == ".mcap" || ext == ".db3") {
        files.push_back(entry.path());
      }
    }
    std::sort(files.begin(), files.end());
  }
  if (files.empty()) {
    throw Error(folder.string(), "",
                "bag folder without storage files (expected relative_file_paths in " +
                    std::string(kBagMetadata) + ", or .mcap or .db3 files)");
  }
  return files;
}

}  // namespace

bool looksLikeRosBag(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    return std::filesystem::is_regular_file(path / kBagMetadata, ec);
  }
  switch (bagFileKind(path)) {
    case BagFileKind::Mcap:
      return true;
    case BagFileKind::Sqlite:
      return sqliteHasMessagesTable(path);
    case BagFileKind::None:
      break;
  }
  return false;
}

std::unique_ptr<RosBag> openRosBag(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_directory(path, ec)) {
    return openBagFile(path);
  }
  std::vector<std::unique_ptr<RosBag>> parts;
  for (const std::filesystem::path& file : folderFiles(path)) {
    parts.push_back(openBagFile(file));
  }
  return std::make_unique<FolderBag>(path, std::move(parts));
}

}  // namespace sonarcarve
