#include "io/files/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cerrno>
#include <cstring>

#include "common/error.h"
#include "io/files/file_kind.h"

namespace sonarcarve {
namespace {

[[noreturn]] void refuse(const std::filesystem::path& path, mode_t mode, std::string_view what) {
  throw Error(path.string(), "",
              "is " + fileKindName(mode) + ": expected a regular file (" + std::string(what) + ")");
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

std::string readInputFile(const std::filesystem::path& path, std::string_view what) {
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
  std::string bytes;
  bytes.reserve(static_cast<std::size_t>(st.st_size));
  char buffer[1 << 16];
  while (true) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
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
  }
  ::close(fd);
  return bytes;
}

std::string_view withoutByteOrderMark(std::string_view text) {
  constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";
  return text.substr(0, kUtf8Bom.size()) == kUtf8Bom ? text.substr(kUtf8Bom.size()) : text;
}

}  // namespace sonarcarve
