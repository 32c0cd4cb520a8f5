#include "io/files/mapped_file.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>

#include "common/error.h"
#include "io/files/input_file.h"

namespace sonarcarve {

std::shared_ptr<const MappedFile> MappedFile::map(const std::filesystem::path& path,
                                                  std::string_view what) {
  const std::string file = path.string();
  requireRegularFile(path, what);
  // Non-blocking: should the path turn into a FIFO after the check, opening it cannot hang.
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) {
    throw Error(file, "", "cannot open file (missing or unreadable)");
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    throw Error(file, "", "not a regular file");
  }
  std::shared_ptr<MappedFile> mapped(new MappedFile());
  const auto size = static_cast<std::size_t>(st.st_size);
  if (size > 0) {
    void* map = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0);
    if (map == MAP_FAILED) {
      ::close(fd);
      throw Error(file, "", "cannot map the file into memory");
    }
    mapped->map_ = map;
    mapped->map_size_ = size;
    mapped->bytes_ = {static_cast<const std::uint8_t*>(map), size};
  }
  mapped->fd_ = fd;
  return mapped;
}

std::shared_ptr<const MappedFile> MappedFile::fromBytes(std::vector<std::uint8_t> bytes) {
  std::shared_ptr<MappedFile> held(new MappedFile());
  held->owned_ = std::move(bytes);
  held->bytes_ = held->owned_;
  return held;
}

MappedFile::~MappedFile() {
  if (map_ != nullptr) {
    ::munmap(map_, map_size_);
  }
  if (fd_ >= 0) {
    ::close(fd_);
  }
}

std::size_t MappedFile::dataAtOrAfter(std::size_t offset) const {
  if (fd_ < 0 || offset >= bytes_.size()) {
    return offset;
  }
  const off_t data = ::lseek(fd_, static_cast<off_t>(offset), SEEK_DATA);
  if (data >= 0) {
    return std::min(static_cast<std::size_t>(data), bytes_.size());
  }
  return errno == ENXIO ? bytes_.size() : offset;  // ENXIO: only a hole up to the end
}

}  // namespace sonarcarve
