// Our MCAP reader (format: mcap.dev/spec), for ROS 2 bags. It reads the data section from the
// front, record by record, and never needs the summary section: a file cut short by a crash
// has none, and its complete records are all read. Schemas, channels and messages are taken
// from the data section and from inside chunks (uncompressed, lz4 frames or zstd frames; the
// chunk's CRC is checked when the writer computed one). A chunk that cannot be decompressed
// or holds a corrupt record is reported and skipped; reading goes on with the next record,
// whose place the chunk's length gives.
#include <zlib.h>

#include <algorithm>
#include <cstring>
#include <map>
#include <mutex>

#include "common/error.h"
#include "common/input_limits.h"
#include "io/files/decompress.h"
#include "io/files/mapped_file.h"
#include "io/rosbag/mcap_format.h"
#include "io/rosbag/ros_bag.h"

namespace sonarcarve {
namespace {

using Bytes = std::span<const std::uint8_t>;

// A bounds-checked little-endian view of a record's content; errors name the file and the
// place of the record ("byte 1234" or "chunk at byte 99, byte 56 of its records").
class RecordReader {
 public:
  RecordReader(Bytes content, const std::string& source, std::string place)
      : content_(content), source_(source), place_(std::move(place)) {}

  template <typename T>
  T read(const char* what) {
    require(sizeof(T), what);
    T value{};
    std::memcpy(&value, content_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return value;
  }
  std::string string(const char* what) {
    const Bytes b = prefixed<std::uint32_t>(what);
    return {reinterpret_cast<const char*>(b.data()), b.size()};
  }
  template <typename Length>
  Bytes prefixed(const char* what) {
    const auto size = read<Length>(what);
    require(size, what);
    const Bytes b = content_.subspan(pos_, static_cast<std::size_t>(size));
    pos_ += static_cast<std::size_t>(size);
    return b;
  }
  Bytes rest() {
    const Bytes b = content_.subspan(pos_);
    pos_ = content_.size();
    return b;
  }
  std::size_t pos() const { return pos_; }
  [[noreturn]] void fail(const std::string& what) const { throw Error(source_, place_, what); }

 private:
  void require(std::uint64_t size, const char* what) const {
    if (content_.size() - pos_ < size) {
      fail(std::string("record ends early: expected ") + what + " (" + std::to_string(size) +
           " bytes, " + std::to_string(content_.size() - pos_) + " left)");
    }
  }
  Bytes content_;
  const std::string& source_;
  std::string place_;
  std::size_t pos_ = 0;
};

std::string opcodeName(std::uint8_t op) {
  char text[8];
  std::snprintf(text, sizeof text, "0x%02X", op);
  return text;
}

struct Chunk {
  std::size_t offset = 0;  ///< of the chunk record in the file
  std::string compression;
  Bytes records;  ///< as stored (compressed or not)
  std::uint64_t uncompressed_size = 0;
  std::uint32_t crc = 0;
};

struct Location {
  std::int64_t chunk = -1;  ///< -1: in the data section
  std::size_t offset = 0;   ///< of the payload, in the file or in the uncompressed chunk
  std::size_t size = 0;
};

class McapBag final : public RosBag {
 public:
  McapBag(std::filesystem::path path, std::shared_ptr<const MappedFile> file)
      : path_(std::move(path)), source_(path_.string()), file_(std::move(file)) {
    index();
  }

  const std::filesystem::path& path() const override { return path_; }
  std::string storage() const override {
    std::string kinds;
    for (const std::string& c : compressions_) {
      kinds += (kinds.empty() ? "" : ", ") + (c.empty() ? std::string("uncompressed") : c);
    }
    return "MCAP" + (kinds.empty() ? std::string() : " (" + kinds + " chunks)");
  }
  const std::vector<BagTopic>& topics() const override { return topics_; }
  const std::vector<BagMessage>& messages() const override { return messages_; }
  const std::vector<std::string>& problems() const override { return problems_; }

  std::vector<std::uint8_t> payload(const BagMessage& message) const override {
    const Location& at = locations_.at(message.locator);
    if (at.chunk < 0) {
      const Bytes b = file_->bytes().subspan(at.offset, at.size);
      return {b.begin(), b.end()};
    }
    const std::lock_guard lock(cache_mutex_);
    if (cached_chunk_ != at.chunk) {
      cached_ = uncompressed(chunks_.at(static_cast<std::size_t>(at.chunk)));
      cached_chunk_ = at.chunk;
    }
    if (at.offset + at.size > cached_.size()) {
      throw Error(source_, message.place, "message lies outside its chunk");
    }
    return {cached_.begin() + static_cast<std::ptrdiff_t>(at.offset),
            cached_.begin() + static_cast<std::ptrdiff_t>(at.offset + at.size)};
  }

 private:
  void index();
  void readRecords(Bytes records, std::int64_t chunk, std::size_t base);
  void handle(std::uint8_t op, Bytes content, std::int64_t chunk, std::size_t at,
              const std::string& place);
  void readChunk(Bytes content, std::size_t offset, const std::string& place);
  std::vector<std::uint8_t> uncompressed(const Chunk& chunk) const;

  std::filesystem::path path_;
  std::string source_;
  std::shared_ptr<const MappedFile> file_;
  std::vector<BagTopic> topics_;
  std::vector<BagMessage> messages_;
  std::vector<Location> locations_;
  std::vector<std::uint16_t> message_channels_;
  std::vector<std::string> problems_;
  std::vector<Chunk> chunks_;
  std::vector<std::string> compressions_;
  std::map<std::uint16_t, std::pair<std::string, std::string>> schemas_;  ///< name, ros2msg text
  std::map<std::uint16_t, std::size_t> channels_;                         ///< -> topics_
  bool ended_ = false;

  mutable std::mutex cache_mutex_;
  mutable std::int64_t cached_chunk_ = -1;
  mutable std::vector<std::uint8_t> cached_;
};

void McapBag::index() {
  const Bytes bytes = file_->bytes();
  if (bytes.empty()) {
    throw Error(source_, bytePlace(0), "empty file: expected an MCAP bag");
  }
  if (bytes.size() < mcap::kMagic.size() ||
      !std::equal(mcap::kMagic.begin(), mcap::kMagic.end(), bytes.begin())) {
    throw Error(source_, bytePlace(0),
                "not an MCAP file (expected the magic 89 4D 43 41 50 30 0D 0A)");
  }
  const std::size_t first = mcap::kMagic.size();
  if (bytes.size() - first < mcap::kRecordHeaderSize || bytes[first] != mcap::kHeader) {
    throw Error(source_, bytePlace(first), "expected the Header record (opcode 0x01)");
  }
  readRecords(bytes.subspan(first), -1, first);
  if (!ended_) {
    problems_.push_back(source_ + ": the file ends without a Data End or Footer record: cut " +
                        "short (a recording that crashed?); every complete record was read");
  }
  // Channels may be defined after the messages that use them only in broken files: resolve
  // at the end, and report messages of channels never defined.
  std::vector<BagMessage> kept;
  std::vector<Location> kept_locations;
  std::size_t orphans = 0;
  for (std::size_t i = 0; i < messages_.size(); ++i) {
    const auto channel = channels_.find(message_channels_[i]);
    if (channel == channels_.end()) {
      ++orphans;
      continue;
    }
    BagMessage m = messages_[i];
    m.topic = channel->second;
    m.locator = kept_locations.size();
    ++topics_[m.topic].messages;
    kept.push_back(std::move(m));
    kept_locations.push_back(locations_[i]);
  }
  if (orphans > 0) {
    problems_.push_back(source_ + ": " + std::to_string(orphans) +
                        " messages of channels never defined (expected a Channel record first); "
                        "skipped");
  }
  messages_ = std::move(kept);
  locations_ = std::move(kept_locations);
  message_channels_.clear();
  // A complete file without channels is an empty recording (valid MCAP: metadata or
  // attachments only); one cut short or corrupt before its first channel is refused.
  if (topics_.empty() && (!ended_ || !problems_.empty())) {
    throw Error(source_, bytePlace(first),
                "no Channel record: expected the topics of a bag" +
                    (problems_.empty() ? std::string() : " (" + problems_.front() + ")"));
  }
}

void McapBag::readRecords(Bytes records, std::int64_t chunk, std::size_t base) {
  const std::string chunk_place =
      chunk < 0 ? "" : "chunk at " + bytePlace(chunks_.at(static_cast<std::size_t>(chunk)).offset);
  std::size_t pos = 0;
  while (pos < records.size() && !ended_) {
    const std::size_t at = base + pos;
    const std::string place =
        chunk < 0 ? bytePlace(at)
                  : chunk_place + ", byte " + std::to_string(pos) + " of its records";
    std::string cut;
    std::uint64_t length = 0;
    const std::size_t left = records.size() - pos;
    if (left < mcap::kRecordHeaderSize) {
      cut = "record header cut short (" + std::to_string(left) +
            " of 9 bytes): expected an opcode and a length";
    } else {
      std::memcpy(&length, records.data() + pos + 1, sizeof length);
      if (records[pos] == 0x00) {
        // The MCAP specification reserves opcode 0x00: zeros here are a hole of a sparse file
        // or corruption, which read on as 9-byte records of nothing would take minutes.
        cut = "opcode 0x00 is no MCAP record (zeros: a hole or corrupt data)";
      } else if (length > left - mcap::kRecordHeaderSize) {
        cut = "record " + opcodeName(records[pos]) + " claims " + std::to_string(length) +
              " bytes, only " + std::to_string(left - mcap::kRecordHeaderSize) +
              " left: cut short or corrupt";
      }
    }
    if (!cut.empty()) {
      if (chunk >= 0) {
        throw Error(source_, place, cut);
      }
      // A file cut short (or a corrupt length): nothing after this can be found.
      problems_.push_back(source_ + ": " + place + ": " + cut + "; reading stopped");
      ended_ = true;
      return;
    }
    const std::uint8_t op = records[pos];
    const Bytes content = records.subspan(pos + mcap::kRecordHeaderSize, length);
    pos += mcap::kRecordHeaderSize + length;
    try {
      handle(op, content, chunk, at + mcap::kRecordHeaderSize, place);
    } catch (const Error& e) {
      if (chunk >= 0) {
        throw;  // the chunk is reported as a whole
      }
      problems_.push_back(std::string(e.what()) + "; record skipped");
    }
  }
}

void McapBag::handle(std::uint8_t op, Bytes content, std::int64_t chunk, std::size_t at,
                     const std::string& place) {
  RecordReader in(content, source_, place);
  switch (op) {
    case mcap::kHeader: {
      const std::string profile = in.string("Header.profile");
      if (!profile.empty() && profile != "ros2") {
        in.fail("profile '" + profile + "': expected 'ros2' (a ROS 2 bag)");
      }
      return;
    }
    case mcap::kSchema: {
      const auto id = in.read<std::uint16_t>("Schema.id");
      std::string name = in.string("Schema.name");
      std::string encoding = in.string("Schema.encoding");
      const Bytes data = in.prefixed<std::uint32_t>("Schema.data");
      std::string definition;
      if (encoding == "ros2msg") {
        definition.assign(reinterpret_cast<const char*>(data.data()), data.size());
      }
      schemas_[id] = {std::move(name), std::move(definition)};
      return;
    }
    case mcap::kChannel: {
      const auto id = in.read<std::uint16_t>("Channel.id");
      const auto schema = in.read<std::uint16_t>("Channel.schema_id");
      BagTopic topic;
      topic.name = in.string("Channel.topic");
      topic.encoding = in.string("Channel.message_encoding");
      const auto s = schemas_.find(schema);
      if (schema != 0 && s == schemas_.end()) {
        in.fail("channel '" + topic.name + "' names schema " + std::to_string(schema) +
                ", which no earlier Schema record defines");
      }
      if (schema != 0) {
        topic.type = s->second.first;
        topic.definition = s->second.second;
      }
      if (!channels_.contains(id)) {
        channels_[id] = topics_.size();
        topics_.push_back(std::move(topic));
      }
      return;
    }
    case mcap::kMessage: {
      const auto channel = in.read<std::uint16_t>("Message.channel_id");
      in.read<std::uint32_t>("Message.sequence");
      const auto log_time = in.read<std::uint64_t>("Message.log_time");
      in.read<std::uint64_t>("Message.publish_time");
      const std::size_t offset = at + in.pos();
      const Bytes data = in.rest();
      BagMessage m;
      m.receive_ns = static_cast<std::int64_t>(std::min<std::uint64_t>(log_time, INT64_MAX));
      m.place = "message " + std::to_string(messages_.size()) + " (" + place + ")";
      messages_.push_back(std::move(m));
      message_channels_.push_back(channel);
      locations_.push_back({chunk, offset, data.size()});
      return;
    }
    case mcap::kChunk:
      if (chunk >= 0) {
        in.fail("a Chunk inside a chunk (expected Schema, Channel or Message records)");
      }
      readChunk(content, at - mcap::kRecordHeaderSize, place);
      return;
    case mcap::kDataEnd:
    case mcap::kFooter:
      ended_ = chunk < 0;
      return;
    default:
      // Indexes, attachments, metadata, statistics and unknown records (the format may add
      // some) are not needed to read messages.
      return;
  }
}

void McapBag::readChunk(Bytes content, std::size_t offset, const std::string& place) {
  RecordReader in(content, source_, place);
  Chunk chunk;
  chunk.offset = offset;
  in.read<std::uint64_t>("Chunk.message_start_time");
  in.read<std::uint64_t>("Chunk.message_end_time");
  chunk.uncompressed_size = in.read<std::uint64_t>("Chunk.uncompressed_size");
  chunk.crc = in.read<std::uint32_t>("Chunk.uncompressed_crc");
  chunk.compression = in.string("Chunk.compression");
  chunk.records = in.prefixed<std::uint64_t>("Chunk.records");
  if (chunk.compression != "" && chunk.compression != "lz4" && chunk.compression != "zstd") {
    in.fail("chunk compression '" + chunk.compression +
            "': expected none, 'lz4' or 'zstd'; chunk skipped");
  }
  if (chunk.uncompressed_size > kMaxBagChunkBytes) {
    in.fail("chunk uncompressed_size " + std::to_string(chunk.uncompressed_size) +
            " bytes: expected at most " + std::to_string(kMaxBagChunkBytes) + "; chunk skipped");
  }
  chunks_.push_back(chunk);
  const auto index = static_cast<std::int64_t>(chunks_.size() - 1);
  const std::size_t messages_before = messages_.size();
  try {
    const std::vector<std::uint8_t> records = uncompressed(chunk);
    // Payload offsets inside a chunk are relative to its uncompressed records.
    readRecords(records, index, 0);
  } catch (const Error& e) {
    messages_.resize(messages_before);
    message_channels_.resize(messages_before);
    locations_.resize(messages_before);
    problems_.push_back(std::string(e.what()) + "; chunk skipped");
    return;
  }
  if (std::find(compressions_.begin(), compressions_.end(), chunk.compression) ==
      compressions_.end()) {
    compressions_.push_back(chunk.compression);
  }
}

std::vector<std::uint8_t> McapBag::uncompressed(const Chunk& chunk) const {
  const std::string place = "chunk at " + bytePlace(chunk.offset);
  RecordReader where(chunk.records, source_, place);
  std::vector<std::uint8_t> out;
  if (chunk.compression.empty()) {
    out.assign(chunk.records.begin(), chunk.records.end());
  } else if (chunk.compression == "lz4") {
    out = decompressLz4Frame(chunk.records, chunk.uncompressed_size, source_, place);
  } else {
    out = decompressZstdFrame(chunk.records, chunk.uncompressed_size, source_, place);
  }
  if (out.size() != chunk.uncompressed_size) {
    where.fail("chunk holds " + std::to_string(out.size()) +
               " bytes of records: expected its uncompressed_size, " +
               std::to_string(chunk.uncompressed_size));
  }
  if (chunk.crc != 0) {
    const auto crc =
        static_cast<std::uint32_t>(::crc32(0L, out.data(), static_cast<uInt>(out.size())));
    if (crc != chunk.crc) {
      where.fail("chunk CRC mismatch: the records are corrupt");
    }
  }
  return out;
}

}  // namespace

std::unique_ptr<RosBag> openMcapBag(const std::filesystem::path& path) {
  return std::make_unique<McapBag>(path, MappedFile::map(path, "an MCAP bag"));
}

}  // namespace sonarcarve
