#include "io/oculus/oculus_log.h"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>

#include "common/error.h"
#include "io/files/mapped_file.h"
#include "io/oculus/oculus_resync.h"

namespace sonarcarve {

namespace {

// ViewPoint log format v1 (RmLogHeader, RmLogItem of the public Oculus ViewPoint sources; the
// structures are naturally aligned, so the file header is 48 bytes and the item header 40).
constexpr std::uint32_t kFileMagic = 0x11223344;
constexpr std::uint32_t kItemMagic = 0xaabbccdd;
constexpr std::size_t kFileHeaderSize = 48;
constexpr std::size_t kItemHeaderSize = 40;
constexpr std::uint16_t kItemOculusSonar = 10;
// Written by the ENSTA Bretagne oculus_driver recorder after each sonar item: u64 seconds and
// u64 nanoseconds of the ping's reception time.
constexpr std::uint16_t kItemOculusSonarStamp = 1010;
// Decompressed items above this are treated as corrupt (an Oculus message is < 2 MiB).
constexpr std::uint32_t kMaxItemSize = 64u << 20;
constexpr std::array<std::uint8_t, 16> kSqliteMagic = {'S', 'Q', 'L', 'i', 't', 'e', ' ', 'f',
                                                       'o', 'r', 'm', 'a', 't', ' ', '3', 0};

template <typename T>
T read(std::span<const std::uint8_t> bytes, std::size_t offset) {
  T value{};
  if (offset <= bytes.size() && sizeof(T) <= bytes.size() - offset) {
    std::memcpy(&value, bytes.data() + offset, sizeof(T));
  }
  return value;
}

bool oculusIdAt(std::span<const std::uint8_t> bytes, std::size_t offset) {
  return offset + 2 <= bytes.size() && read<std::uint16_t>(bytes, offset) == kOculusId;
}

std::string messageName(std::uint16_t id) {
  switch (id) {
    case 0x15:
      return "simple fire";
    case 0x22:
      return "full ping result";
    case 0x55:
      return "user config";
    case 0x80:
      return "logs";
    case 0xff:
      return "dummy";
    default:
      return "unknown";
  }
}

std::string itemName(std::uint16_t type) {
  switch (type) {
    case 1:
      return "settings";
    case 2:
      return "serial port";
    case 12:
    case 13:
      return "video";
    case 17:
    case 18:
    case 19:
    case 22:
    case 30:
      return "navigation or attitude";
    case 500:
      return "view information";
    default:
      return "other";
  }
}

// True if the message at `offset` is kept with the size it claims although that size does not
// lead to another message: no confirmed message starts inside it and, for a ping, it decodes.
bool keepsItsSize(std::span<const std::uint8_t> bytes, std::size_t offset, std::size_t next) {
  if (!oculusHeaderFitsAt(bytes, offset)) {
    return false;
  }
  const OculusMessageHeader header = readOculusHeader(bytes, offset, std::string());
  if (next != kNoOculusMessage && next < offset + header.size()) {
    return false;  // a confirmed message starts inside: the size field is corrupt
  }
  return header.msg_id != kOculusSimplePingResult || oculusPingDecodesAt(bytes, offset);
}

// What is wrong with the bytes at `offset` that are skipped up to `next`.
Error corruptionAt(std::span<const std::uint8_t> bytes, std::size_t offset, std::size_t next,
                   const std::string& source) {
  if (!oculusIdAt(bytes, offset)) {
    const std::size_t stop = next != kNoOculusMessage ? next : bytes.size();
    return Error(source, bytePlace(offset),
                 std::to_string(stop - offset) +
                     " bytes that are not an Oculus message (no oculusId 0x4f53)");
  }
  if (next != kNoOculusMessage && !oculusHeaderFitsAt(bytes, offset) &&
      bytes.size() - offset >= kOculusHeaderSize) {
    std::uint32_t payload = 0;
    std::memcpy(&payload, bytes.data() + offset + 10, sizeof payload);
    return Error(source, bytePlace(offset + 10),
                 "payloadSize " + std::to_string(payload) +
                     " is corrupt: it runs past the end of the data, over the next valid "
                     "message, at " +
                     bytePlace(next));
  }
  try {
    const OculusMessageHeader header = readOculusHeader(bytes, offset, source);
    if (next != kNoOculusMessage && next < offset + header.size()) {
      return Error(source, bytePlace(offset + 10),
                   "payloadSize " + std::to_string(header.payload_size) +
                       " is corrupt: it runs over the next valid message, at " + bytePlace(next));
    }
    decodeOculusPing(bytes, offset, source, false);
    return Error(source, bytePlace(offset + header.size()),
                 "expected an Oculus message after the one at " + bytePlace(offset));
  } catch (const Error& e) {
    return e;
  }
}

}  // namespace

void OculusLog::addProblem(const Error& error, const std::string& consequence) {
  if (!first_problem_) {
    first_problem_ = error;
  }
  problems_.push_back(std::string(error.what()) + " (" + consequence + ")");
}

OculusLog OculusLog::open(const std::filesystem::path& path) {
  OculusLog log;
  log.storage_ = MappedFile::map(path, "an Oculus log");
  log.source_ = path.string();
  log.index();
  return log;
}

OculusLog OculusLog::fromBytes(std::vector<std::uint8_t> bytes, std::string source) {
  OculusLog log;
  log.storage_ = MappedFile::fromBytes(std::move(bytes));
  log.source_ = std::move(source);
  log.index();
  return log;
}

void OculusLog::index() {
  const std::span<const std::uint8_t> bytes = storage_->bytes();
  if (bytes.empty()) {
    throw Error(source_, bytePlace(0),
                "empty file: expected Oculus messages or an Oculus ViewPoint recording");
  }
  if (bytes.size() >= kSqliteMagic.size() &&
      std::equal(kSqliteMagic.begin(), kSqliteMagic.end(), bytes.begin())) {
    throw Error(source_, bytePlace(0),
                "an SQLite database (Oculus ViewPoint's newer log format): not supported, "
                "export the recording as a v1 .oculus file (docs/formats.md)");
  }
  if (read<std::uint32_t>(bytes, 0) == kFileMagic) {
    container_ = "oculus viewpoint recording v1";
    time_base_ = "recording item times (seconds, as written by the recorder)";
    indexRecording();
  } else if (oculusIdAt(bytes, 0)) {
    container_ = "oculus messages";
    indexMessages(bytes, 0, bytes.size(), source_, -1, std::nullopt);
    const auto v2 = std::count_if(pings_.begin(), pings_.end(),
                                  [](const auto& e) { return e.ping.header.msg_version == 2; });
    time_base_ = v2 == static_cast<long>(pings_.size())
                     ? "ping start times (message version 2): seconds since sonar power-up"
                     : "ping start times (message version 0/1): pingStartTime read as "
                       "microseconds since sonar power-up (unit not documented)";
  } else {
    throw Error(source_, bytePlace(0),
                "not an Oculus log: expected an Oculus message (oculusId 0x4f53) or an Oculus "
                "ViewPoint recording (0x11223344)");
  }
  if (pings_.empty() && first_problem_) {
    throw Error(first_problem_->source(), first_problem_->place(),
                first_problem_->message() + " (no usable ping in the file)");
  }
  if (pings_.empty()) {
    throw Error(source_, "", "the file holds no simple ping result (message id 35)");
  }
}

void OculusLog::indexMessages(std::span<const std::uint8_t> all, std::size_t begin, std::size_t end,
                              const std::string& source, int item,
                              std::optional<double> item_time_s) {
  // Bounds checks stop at `end` (the end of a recording item, or of the file).
  const std::span<const std::uint8_t> bytes = all.first(end);
  std::map<std::string, std::size_t> skipped;
  std::uint64_t wraps = 0;
  double last_raw_time = -1.0;
  std::size_t offset = begin;
  while (offset < end) {
    if (!oculusSizeLeadsToAMessage(bytes, offset)) {
      // A corrupt header, garbage, or a message followed by garbage: the size is trusted only
      // if no confirmed message starts inside the span it claims.
      const std::size_t next = findNextOculusMessage(bytes, offset + 1, storage_.get());
      if (!keepsItsSize(bytes, offset, next)) {
        offset = skipCorruptBytes(bytes, offset, next, source);
        continue;
      }
    }
    const OculusMessageHeader header = readOculusHeader(bytes, offset, source);
    if (header.msg_id != kOculusSimplePingResult) {
      ++skipped["message id " + std::to_string(header.msg_id) + " (" + messageName(header.msg_id) +
                ")"];
    } else {
      try {
        OculusLogEntry entry{decodeOculusPing(bytes, offset, source, false), 0.0, item};
        if (item_time_s) {
          entry.time_s = *item_time_s;
        } else if (entry.ping.header.msg_version == 2) {
          entry.time_s = entry.ping.ping_start_time;
        } else {
          // u32 microseconds wrap every 71.6 minutes.
          if (last_raw_time >= 0.0 && entry.ping.ping_start_time < last_raw_time) {
            ++wraps;
          }
          last_raw_time = entry.ping.ping_start_time;
          entry.time_s = (entry.ping.ping_start_time + 4294967296.0 * wraps) * 1e-6;
        }
        pings_.push_back(std::move(entry));
      } catch (const Error& e) {
        addProblem(e, "message at " + bytePlace(offset) + " skipped");
        skipped_.bytes += header.size();
        ++skipped_.messages;
      }
    }
    offset += header.size();
  }
  for (const auto& [what, count] : skipped) {
    notes_.push_back(source + ": " + std::to_string(count) + " x " + what + " skipped");
  }
}

std::size_t OculusLog::skipCorruptBytes(std::span<const std::uint8_t> bytes, std::size_t offset,
                                        std::size_t next, const std::string& source) {
  const bool found = next != kNoOculusMessage;
  const std::size_t stop = found ? next : bytes.size();
  const std::size_t count = stop - offset;
  const bool message = oculusIdAt(bytes, offset);
  skipped_.bytes += count;
  skipped_.messages += message ? 1 : 0;
  skipped_.resyncs += found ? 1 : 0;
  const std::string skipped = std::to_string(count) + " bytes" + (message ? " (1 message)" : "");
  const std::string consequence =
      found ? "skipped " + skipped + ", resynchronised on the next valid message at " +
                  bytePlace(next)
      : message ? "the last message is cut off: skipped " + skipped + " up to the end"
                : "skipped " + skipped + " up to the end";
  addProblem(corruptionAt(bytes, offset, next, source), consequence);
  return stop;
}

void OculusLog::indexRecording() {
  const std::span<const std::uint8_t> bytes = storage_->bytes();
  if (bytes.size() < kFileHeaderSize) {
    throw Error(
        source_, bytePlace(bytes.size()),
        "truncated Oculus ViewPoint file header: " + std::to_string(bytes.size()) + " of 48 bytes");
  }
  const auto header_size = read<std::uint32_t>(bytes, 4);
  const auto version = read<std::uint16_t>(bytes, 24);
  const auto encryption = read<std::uint16_t>(bytes, 26);
  if (header_size < kFileHeaderSize || header_size > bytes.size()) {
    throw Error(source_, bytePlace(4),
                "file header size " + std::to_string(header_size) +
                    ": expected at least 48 and within the file");
  }
  if (encryption != 0) {
    throw Error(
        source_, bytePlace(26),
        "encrypted recording (encryption " + std::to_string(encryption) + "): not supported");
  }
  if (version != 1) {
    notes_.push_back(source_ + ": " + bytePlace(24) + ": log version " + std::to_string(version) +
                     ", read as version 1");
  }
  std::map<std::string, std::size_t> skipped;
  std::size_t sonar_items_start = 0;  // first ping of the last sonar item, for time stamps
  std::size_t offset = header_size;
  while (offset < bytes.size()) {
    const std::size_t left = bytes.size() - offset;
    if (left < kItemHeaderSize) {
      addProblem(Error(source_, bytePlace(offset),
                       "truncated item header: " + std::to_string(left) + " of 40 bytes"),
                 "the end of the file is cut off");
      break;
    }
    const auto item_size = read<std::uint32_t>(bytes, offset + 4);
    const bool plausible = read<std::uint32_t>(bytes, offset) == kItemMagic &&
                           item_size >= kItemHeaderSize && item_size <= 4096;
    if (!plausible) {
      std::size_t next = offset + 1;
      while (next + kItemHeaderSize <= bytes.size() &&
             read<std::uint32_t>(bytes, next) != kItemMagic) {
        ++next;
      }
      const bool found = next + kItemHeaderSize <= bytes.size();
      skipped_.bytes += (found ? next : bytes.size()) - offset;
      skipped_.resyncs += found ? 1 : 0;
      addProblem(Error(source_, bytePlace(offset),
                       "expected a recording item (0xaabbccdd with a header size of 40)"),
                 found ? "skipped " + std::to_string(next - offset) + " bytes to the next item"
                       : std::string("skipped the rest of the file"));
      if (!found) {
        break;
      }
      offset = next;
      continue;
    }
    const auto type = read<std::uint16_t>(bytes, offset + 8);
    const auto time_s = read<double>(bytes, offset + 16);
    const auto compression = read<std::uint16_t>(bytes, offset + 24);
    const auto original_size = read<std::uint32_t>(bytes, offset + 28);
    const auto payload_size = read<std::uint32_t>(bytes, offset + 32);
    const std::size_t payload = offset + item_size;
    if (payload > bytes.size() || payload_size > bytes.size() - payload) {
      addProblem(Error(source_, bytePlace(offset + 32),
                       "truncated item: a payload of " + std::to_string(payload_size) +
                           " bytes runs past the end of the file"),
                 "the last item is cut off");
      break;
    }
    const std::size_t end = payload + payload_size;
    if (type == kItemOculusSonar) {
      sonar_items_start = pings_.size();
      if (compression == 0) {
        indexMessages(bytes, payload, end, source_, -1, time_s);
      } else if (compression == 1) {
        compressed_items_.push_back({payload, payload_size, original_size});
        const int item = static_cast<int>(compressed_items_.size() - 1);
        try {
          const std::vector<std::uint8_t> inflated = inflateItem(compressed_items_.size() - 1);
          indexMessages(inflated, 0, inflated.size(),
                        source_ + " (compressed item at " + bytePlace(offset) + ")", item, time_s);
        } catch (const Error& e) {
          addProblem(e, "item skipped");
        }
      } else {
        addProblem(Error(source_, bytePlace(offset + 24),
                         "unknown compression " + std::to_string(compression)),
                   "item skipped");
      }
    } else if (type == kItemOculusSonarStamp && payload_size == 16) {
      const double stamp = static_cast<double>(read<std::uint64_t>(bytes, payload)) +
                           1e-9 * static_cast<double>(read<std::uint64_t>(bytes, payload + 8));
      for (std::size_t i = sonar_items_start; i < pings_.size(); ++i) {
        pings_[i].time_s = stamp;
      }
    } else {
      ++skipped["item type " + std::to_string(type) + " (" + itemName(type) + ")"];
    }
    offset = end;
  }
  for (const auto& [what, count] : skipped) {
    notes_.push_back(source_ + ": " + std::to_string(count) + " x " + what + " skipped");
  }
}

std::vector<std::uint8_t> OculusLog::inflateItem(std::size_t item) const {
  // qCompress: the uncompressed size as a big-endian u32, then a zlib stream.
  const CompressedItem& c = compressed_items_.at(item);
  const std::span<const std::uint8_t> bytes = storage_->bytes();
  const std::string where = source_;
  if (c.payload_size < 4) {
    throw Error(where, bytePlace(c.payload_offset),
                "compressed item too short for its 4-byte size prefix");
  }
  const std::uint8_t* p = bytes.data() + c.payload_offset;
  const std::uint32_t expected = (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) |
                                 (std::uint32_t{p[2]} << 8) | std::uint32_t{p[3]};
  if (expected == 0 || expected > kMaxItemSize || expected != c.original_size) {
    throw Error(where, bytePlace(c.payload_offset),
                "compressed item declares " + std::to_string(expected) +
                    " bytes uncompressed, the item header " + std::to_string(c.original_size) +
                    " (expected equal, at most 64 MiB)");
  }
  std::vector<std::uint8_t> out(expected);
  uLongf out_size = expected;
  const int rc = ::uncompress(out.data(), &out_size, p + 4, c.payload_size - 4);
  if (rc != Z_OK || out_size != expected) {
    throw Error(where, bytePlace(c.payload_offset + 4),
                "corrupt compressed item (zlib error " + std::to_string(rc) + ")");
  }
  return out;
}

std::string OculusLog::skippedSummary() const {
  if (skipped_.bytes == 0) {
    return "";
  }
  return source_ + ": skipped " + std::to_string(skipped_.bytes) + " corrupt bytes (" +
         std::to_string(skipped_.messages) + " messages), resynchronised " +
         std::to_string(skipped_.resyncs) + " times on the next valid message";
}

OculusPing OculusLog::decode(std::size_t index) const {
  const OculusLogEntry& entry = pings_.at(index);
  const std::size_t offset = entry.ping.header.offset;
  if (entry.item >= 0) {
    const std::vector<std::uint8_t> inflated = inflateItem(static_cast<std::size_t>(entry.item));
    return decodeOculusPing(inflated, offset, source_ + " (compressed item)");
  }
  return decodeOculusPing(storage_->bytes(), offset, source_);
}

bool looksLikeOculusLog(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  std::array<std::uint8_t, 4> head{};
  in.read(reinterpret_cast<char*>(head.data()), head.size());
  if (in.gcount() < 2) {
    return false;
  }
  return read<std::uint16_t>(head, 0) == kOculusId ||
         (in.gcount() == 4 && read<std::uint32_t>(head, 0) == kFileMagic);
}

}  // namespace sonarcarve
