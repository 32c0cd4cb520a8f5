// Oculus logs: the files analysts bring from a Blueprint Subsea Oculus sonar
// (docs/formats.md, "Oculus logs"). Two kinds are read:
//   - message streams: Oculus network messages back to back (a capture of the sonar's TCP
//     stream, or liboculus' raw files); frame times come from the pings' own time fields;
//   - recordings made by Oculus ViewPoint (".oculus", log format v1): a 48-byte file header
//     (magic 0x11223344) and items of a 40-byte header (magic 0xaabbccdd) and a payload, plain
//     or qCompress'ed; items of type 10 hold Oculus messages; frame times come from the items.
// ViewPoint's later SQLite logs are recognised and refused with a clear error.
//
// Opening a log indexes it: every message is checked (headers, sizes, bearing tables) but
// images are converted only by decode(). The file is memory-mapped, so a log of any size is
// opened without reading it into memory. A message that is corrupt is reported in problems()
// and skipped, the rest kept; after a corrupt header (a flipped bit in a size field, garbage)
// the reader scans forward to the next valid message (io/oculus/oculus_resync.h) and counts the
// bytes and messages it skipped (skipped()); messages other than pings (status, user config, ...)
// are listed in notes() and skipped; a truncated last message is reported. A file with no usable
// ping throws an Error naming the file and the byte offset.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "common/error.h"
#include "io/oculus/oculus_message.h"

namespace sonarcarve {

class MappedFile;

struct OculusLogEntry {
  OculusPing ping;      ///< decoded without the image
  double time_s = 0.0;  ///< on the sonar's clock (see OculusLog::timeBase())
  int item = -1;        ///< compressed recording item that holds it, or -1
};

/// What the reader skipped as corrupt: bytes, messages among them (a corrupt header, a
/// message that does not decode, a cut-off last message) and how often it had to scan
/// forward for the next valid message.
struct OculusSkipped {
  std::size_t bytes = 0;
  std::size_t messages = 0;
  std::size_t resyncs = 0;
};

class OculusLog {
 public:
  /// Maps and indexes `path`. Throws Error (file, byte, what was expected) on an empty,
  /// unrecognised, encrypted or unusable file.
  static OculusLog open(const std::filesystem::path& path);
  /// The same from bytes in memory; `source` names them in messages.
  static OculusLog fromBytes(std::vector<std::uint8_t> bytes, std::string source);

  const std::string& source() const { return source_; }
  /// "oculus messages" or "oculus viewpoint recording v1".
  const std::string& container() const { return container_; }
  /// Where frame times come from, in words (for reports and `info`).
  const std::string& timeBase() const { return time_base_; }
  const std::vector<OculusLogEntry>& pings() const { return pings_; }
  /// Skipped content that is not an error (other message and item types), one line each.
  const std::vector<std::string>& notes() const { return notes_; }
  /// Corrupt or truncated data that was skipped, one line each with its byte offset.
  const std::vector<std::string>& problems() const { return problems_; }
  /// The totals of problems(); all zero for an intact log.
  const OculusSkipped& skipped() const { return skipped_; }
  /// skipped() in words for `info` and warnings ("" if nothing was skipped).
  std::string skippedSummary() const;

  /// Ping `index` with its image. Throws Error if it cannot be decoded.
  OculusPing decode(std::size_t index) const;

  struct CompressedItem {
    std::size_t payload_offset = 0;
    std::uint32_t payload_size = 0;
    std::uint32_t original_size = 0;
  };

 private:
  OculusLog() = default;
  void index();
  void indexMessages(std::span<const std::uint8_t> bytes, std::size_t begin, std::size_t end,
                     const std::string& source, int item, std::optional<double> item_time_s);
  std::size_t skipCorruptBytes(std::span<const std::uint8_t> bytes, std::size_t offset,
                               std::size_t next, const std::string& source);
  void indexRecording();
  std::vector<std::uint8_t> inflateItem(std::size_t item) const;
  void addProblem(const Error& error, const std::string& consequence);

  std::shared_ptr<const MappedFile> storage_;
  std::string source_;
  std::string container_;
  std::string time_base_;
  std::vector<OculusLogEntry> pings_;
  std::vector<CompressedItem> compressed_items_;
  std::vector<std::string> notes_;
  std::vector<std::string> problems_;
  OculusSkipped skipped_;
  std::optional<Error> first_problem_;
};

/// True if the file starts like an Oculus message stream or an Oculus ViewPoint recording
/// (reads the first bytes only; false for a missing file or a folder).
bool looksLikeOculusLog(const std::filesystem::path& path);

}  // namespace sonarcarve
