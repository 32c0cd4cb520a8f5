// MappedFile: the read-only bytes of an input file, memory-mapped so that a recording of any
// size is opened without reading it into memory (or bytes already in memory, for tests and
// fuzzing). Shared by the binary readers (Oculus logs, MCAP bags). Immutable; safe to share
// between threads.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

namespace sonarcarve {

class MappedFile {
 public:
  /// Maps `path` (a regular file, checked as by requireRegularFile; `what` names the expected
  /// content in messages). Throws Error naming the file if it cannot be opened or mapped.
  static std::shared_ptr<const MappedFile> map(const std::filesystem::path& path,
                                               std::string_view what);
  /// Bytes already in memory.
  static std::shared_ptr<const MappedFile> fromBytes(std::vector<std::uint8_t> bytes);

  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;
  ~MappedFile();

  std::span<const std::uint8_t> bytes() const { return bytes_; }

  /// The first offset at or after `offset` that is not in a hole of a sparse file (a hole
  /// reads as zeros and holds no data: a scan for the next record may jump over it), or the
  /// size when only holes are left. `offset` itself for bytes in memory, or when the file
  /// system cannot say (lseek SEEK_DATA).
  std::size_t dataAtOrAfter(std::size_t offset) const;

 private:
  MappedFile() = default;
  std::vector<std::uint8_t> owned_;
  void* map_ = nullptr;
  std::size_t map_size_ = 0;
  int fd_ = -1;  ///< kept open for dataAtOrAfter
  std::span<const std::uint8_t> bytes_;
};

}  // namespace sonarcarve
