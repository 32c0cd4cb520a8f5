// OccupancyStore: the map.bt export blocks an evicting run collects as its pages are settled
// (carve/occupancy_export.h), kept as their Morton keys in memory (16 bytes a block) and their
// leaves (128 bytes) in an anonymous temporary file (io/files/temporary_file.h), so
// that what a long survey holds for its map.bt grows by a ninth of the blocks' size. Copies
// share the file. Blocks the file cannot take (no temporary directory, a full disk) are kept
// in memory instead, and problem() says why.
#pragma once

#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "carve/occupancy_export.h"

namespace sonarcarve {

class OccupancyStore {
 public:
  void add(const std::vector<OccupancyBlock>& blocks);
  std::size_t size() const { return keys_.size(); }
  bool empty() const { return keys_.empty(); }
  /// Why blocks are kept in memory instead of the file; empty while the file takes them.
  const std::string& problem() const { return problem_; }
  /// The blocks in Morton order: their keys, and a reader of the n-th. Throws Error if the
  /// file cannot be read back.
  SortedOccupancy sorted() const;

 private:
  struct Key {
    std::uint64_t morton = 0;
    std::uint64_t record = 0;  // place in the file, in blocks
  };
  static constexpr std::uint64_t kInMemory = std::uint64_t{1} << 63;  // record: in kept_
  void writeToFile(const std::vector<OccupancyBlock>& blocks);
  std::vector<Key> keys_;
  std::shared_ptr<std::FILE> file_;
  std::vector<OccupancyBlock> kept_;
  std::string problem_;
};

}  // namespace sonarcarve
