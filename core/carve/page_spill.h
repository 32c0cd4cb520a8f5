// PageSpill: pages of a VoxelMap set aside in an anonymous temporary file while no frame
// reaches them, and held again, exactly as they were, before one does (an evicting run whose
// survey comes back over ground it left: docs/scaling.md, "Pages set aside"). The file is an
// anonymous temporary file (io/files/temporary_file.h); the room of a page held again is reused by
// the next pages set aside, so the file is about as large as the most pages set aside at once (free
// room is joined with its neighbours).
#pragma once

#include <cstdint>
#include <cstdio>
#include <map>
#include <memory>
#include <unordered_map>
#include <vector>

#include "carve/voxel_map.h"

namespace sonarcarve {

class PageSpill {
 public:
  /// Throws Error if no temporary file can be made.
  PageSpill();

  /// Writes a held page of `map` to the file and lets it go. Throws Error (the page still
  /// held) if the file cannot take it.
  void setAside(VoxelMap& map, std::size_t page);
  /// Holds a page set aside again, as it was. No-op for a page not set aside.
  void holdAgain(VoxelMap& map, std::size_t page);

  bool isAside(std::size_t page) const { return aside_.count(page) != 0; }
  std::size_t pagesAside() const { return aside_.size(); }
  std::size_t pagesSetAside() const { return set_aside_; }  ///< over the run
  std::uint64_t fileBytes() const { return end_; }  ///< up to the end of the last page aside

 private:
  struct Extent {
    std::uint64_t offset = 0;
    std::uint64_t size = 0;
  };
  Extent place(std::uint64_t size);
  void giveBack(const Extent& extent);

  struct Close {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  std::unique_ptr<std::FILE, Close> file_;
  std::unordered_map<std::size_t, Extent> aside_;
  // Free extents, by offset (to join neighbours) and by size (to take the smallest that fits).
  std::map<std::uint64_t, std::uint64_t> room_at_;       // offset -> size
  std::multimap<std::uint64_t, std::uint64_t> room_of_;  // size -> offset
  void forgetRoom(std::uint64_t offset, std::uint64_t size);
  std::uint64_t end_ = 0;
  std::size_t set_aside_ = 0;
};

}  // namespace sonarcarve
