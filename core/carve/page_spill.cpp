#include "carve/page_spill.h"

#include <cerrno>
#include <cstring>
#include <iterator>
#include <string>

#include "common/error.h"
#include "io/files/temporary_file.h"

namespace sonarcarve {
namespace {

constexpr const char* kSource = "temporary file of map pages set aside";

std::string pageName(std::size_t page) {
  return "page " + std::to_string(page);
}

void seekTo(std::FILE* file, std::uint64_t offset, std::size_t page) {
  if (fseeko(file, static_cast<off_t>(offset), SEEK_SET) != 0) {
    throw Error(kSource, pageName(page),
                "could not seek to byte " + std::to_string(offset) + ": " + std::strerror(errno));
  }
}

}  // namespace

PageSpill::PageSpill() : file_(openTemporaryFile(kSource)) {}

PageSpill::Extent PageSpill::place(std::uint64_t size) {
  const auto fit = room_of_.lower_bound(size);
  if (fit == room_of_.end()) {
    const Extent at{end_, size};
    end_ += size;
    return at;
  }
  const std::uint64_t room_size = fit->first;
  const std::uint64_t offset = fit->second;
  forgetRoom(offset, room_size);
  if (room_size > size) {
    room_at_.emplace(offset + size, room_size - size);
    room_of_.emplace(room_size - size, offset + size);
  }
  return {offset, size};
}

void PageSpill::forgetRoom(std::uint64_t offset, std::uint64_t size) {
  room_at_.erase(offset);
  for (auto [it, end] = room_of_.equal_range(size); it != end; ++it) {
    if (it->second == offset) {
      room_of_.erase(it);
      return;
    }
  }
}

void PageSpill::giveBack(const Extent& extent) {
  std::uint64_t offset = extent.offset;
  std::uint64_t size = extent.size;
  const auto after = room_at_.find(offset + size);
  if (after != room_at_.end()) {
    const std::uint64_t after_size = after->second;
    forgetRoom(offset + size, after_size);
    size += after_size;
  }
  const auto next = room_at_.lower_bound(offset);
  if (next != room_at_.begin()) {
    const auto before = std::prev(next);
    if (before->first + before->second == offset) {
      const std::uint64_t before_offset = before->first;
      const std::uint64_t before_size = before->second;
      forgetRoom(before_offset, before_size);
      offset = before_offset;
      size += before_size;
    }
  }
  if (offset + size == end_) {
    end_ = offset;  // the file's tail is free: the next page goes there
    return;
  }
  room_at_.emplace(offset, size);
  room_of_.emplace(size, offset);
}

void PageSpill::setAside(VoxelMap& map, std::size_t page) {
  if (!map.pageHeld(page) || isAside(page)) {
    return;
  }
  const std::vector<std::uint8_t> bytes = map.packPage(page);
  const Extent at = place(bytes.size());
  seekTo(file_.get(), at.offset, page);
  if (std::fwrite(bytes.data(), 1, bytes.size(), file_.get()) != bytes.size() ||
      std::fflush(file_.get()) != 0) {
    const std::string why = std::strerror(errno);
    giveBack(at);
    throw Error(kSource, pageName(page),
                "could not write " + std::to_string(bytes.size()) + " bytes at byte " +
                    std::to_string(at.offset) + " (disk full?): " + why);
  }
  aside_.emplace(page, at);
  map.releasePage(page);
  ++set_aside_;
}

void PageSpill::holdAgain(VoxelMap& map, std::size_t page) {
  const auto it = aside_.find(page);
  if (it == aside_.end()) {
    return;
  }
  const Extent at = it->second;
  std::vector<std::uint8_t> bytes(at.size);
  seekTo(file_.get(), at.offset, page);
  if (std::fread(bytes.data(), 1, bytes.size(), file_.get()) != bytes.size()) {
    throw Error(kSource, pageName(page),
                "could not read back " + std::to_string(at.size) + " bytes at byte " +
                    std::to_string(at.offset));
  }
  map.unpackPage(page, bytes);
  aside_.erase(it);
  giveBack(at);
}

}  // namespace sonarcarve
