#include "io/files/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <algorithm>
#include <cerrno>
#include <cstring>

#include "common/available_memory.h"
#include "common/error.h"
#include "io/files/file_kind.h"

namespace sonarcarve {
namespace {

[[noreturn]] void refuse(const std::filesystem::path& path, mode_t mode, std::string_view what) {
  throw Error(path.string(), "",
              "is " + fileKindName(mode) + ": expected a regular file (" + std::string(what) + ")");
}

// Reading a file whole takes its size in memory: more than the memory left ends the process.
// Files below this are not checked against it (reading /proc for every frame costs time).
constexpr std::uint64_t kCheckMemoryAbove = std::uint64_t{256} << 20;

void requireReadableSize(const std::filesystem::path& path, std::uint64_t size,
                         std::string_view what, std::uint64_t max_bytes) {
  if (size > max_bytes) {
    throw Error(path.string(), "",
                "is " + std::to_string(size) + " bytes, more than the " +
                    std::to_string(max_bytes) + " bytes " + std::string(what) +
                    " may have (docs/reliability.md, \"Limits\"): not read");
  }
  if (size > kCheckMemoryAbove) {
    if (const auto memory = availableMemory(); memory && size > memory->bytes) {
      throw Error(path.string(), "",
                  "is " + std::to_string(size >> 20) + " MiB, more than the " +
                      std::to_string(memory->bytes >> 20) + " MiB of memory available (" +
                      memory->source + "): not read");
    }
  }
}

}  // namespace

void requireRegularFile(const std::filesystem::path& path, std::string_view what) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    const int error = errno;
    throw Error(path.string(), "",
                (error == ENOENT ? std::string("not found") : std::strerror(error)) +
                    ": expected " + std::string(what));
  }
  if (!S_ISREG(st.st_mode)) {
    refuse(path, st.st_mode, what);
  }
}

void requireInputSize(const std::filesystem::path& path, std::string_view what,
                      std::uint64_t max_bytes) {
  requireRegularFile(path, what);
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (!ec) {
    requireReadableSize(path, size, what, max_bytes);
  }
}

std::string readInputFile(const std::filesystem::path& path, std::string_view what,
                          std::uint64_t max_bytes) {
  requireRegularFile(path, what);
  // Non-blocking: should the path turn into a FIFO after the check, opening it cannot hang.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) {
    throw Error(
        path.string(), "",
        std::string("cannot open: ") + std::strerror(errno) + " (" + std::string(what) + ")");
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    refuse(path, st.st_mode, what);
  }
  const auto size = static_cast<std::uint64_t>(st.st_size);
  try {
    requireReadableSize(path, size, what, max_bytes);
  } catch (...) {
    ::close(fd);
    throw;
  }
  std::string bytes;
  bytes.reserve(static_cast<std::size_t>(size));
  char buffer[1 << 16];
  while (true) {
    // A file that grows while it is read stops at one byte past the bound, and is refused.
    const std::uint64_t room = max_bytes + 1 - std::min<std::uint64_t>(bytes.size(), max_bytes);
    const ssize_t n = ::read(fd, buffer, std::min<std::uint64_t>(sizeof buffer, room));
    if (n == 0) {
      break;
    }
    if (n < 0) {
      if (errno == EINTR) {
        continue;
      }
      const int error = errno;
      ::close(fd);
      throw Error(path.string(), bytePlace(bytes.size()),
                  std::string("read failed: ") + std::strerror(error));
    }
    bytes.append(buffer, static_cast<std::size_t>(n));
    if (bytes.size() > max_bytes) {
      ::close(fd);
      requireReadableSize(path, bytes.size(), what, max_bytes);
    }
  }
  ::close(fd);
  return bytes;
}

std::string_view withoutByteOrderMark(std::string_view text) {
  constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";
  return text.substr(0, kUtf8Bom.size()) == kUtf8Bom ? text.substr(kUtf8Bom.size()) : text;
}

}  // namespace sonarcarve
