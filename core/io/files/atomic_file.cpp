#include "io/files/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cerrno>
#include <cstring>
#include <string>

#include "common/error.h"
#include "io/files/file_kind.h"

namespace sonarcarve {
namespace {

std::string cause(int error) {
  std::string text = std::strerror(error);
  if (error == ENOSPC || error == EDQUOT || error == EFBIG) {
    text += " (disk full or file size limit)";
  }
  return text;
}

// A file descriptor that is closed once, on every path out.
class WriteDescriptor {
 public:
  explicit WriteDescriptor(const std::filesystem::path& file)
      : fd_(::open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666)) {}
  ~WriteDescriptor() {
    if (fd_ >= 0) {
      ::close(fd_);
    }
  }
  WriteDescriptor(const WriteDescriptor&) = delete;
  WriteDescriptor& operator=(const WriteDescriptor&) = delete;
  int get() const { return fd_; }
  /// Closes now; returns the errno of a failed close (NFS reports write errors there), or 0.
  int close() {
    const int result = ::close(fd_);
    fd_ = -1;
    return result == 0 ? 0 : errno;
  }

 private:
  int fd_;
};

// Writes every byte, then syncs: returns the errno of the first failure, or 0.
int writeAndSync(int fd, std::string_view bytes, std::size_t& written) {
  written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0 && errno == EINTR) {
      continue;
    }
    if (n <= 0) {
      return n < 0 ? errno : ENOSPC;
    }
    written += static_cast<std::size_t>(n);
  }
  return ::fsync(fd) == 0 ? 0 : errno;
}

void writeTemporary(const std::filesystem::path& path, const std::filesystem::path& folder,
                    const std::filesystem::path& tmp, std::string_view bytes) {
  WriteDescriptor fd(tmp);
  if (fd.get() < 0) {
    throw Error(path.string(), "",
                "cannot create a file in " + folder.string() + ": " + cause(errno));
  }
  std::size_t written = 0;
  int error = writeAndSync(fd.get(), bytes, written);
  struct stat st {};
  if (error == 0 && (::fstat(fd.get(), &st) != 0 || st.st_size != static_cast<off_t>(written))) {
    error = EIO;
  }
  if (error == 0) {
    error = fd.close();
  }
  if (error != 0) {
    throw Error(path.string(), bytePlace(written),
                "write failed: " + cause(error) + "; previous file kept");
  }
}

constexpr int kMaxLinks = 40;  // as the kernel's own limit (ELOOP)

// `target` is where `links` symbolic links from `path` led.
[[noreturn]] void refuseTarget(const std::filesystem::path& path, int links,
                               const std::filesystem::path& target, const std::string& what) {
  const std::string through =
      links == 0 ? "is " : "is a symbolic link to " + target.string() + ", which is ";
  throw Error(path.string(), "", through + what + ": expected a regular file or a new path");
}

std::filesystem::path linkTarget(const std::filesystem::path& link) {
  std::error_code ec;
  const std::filesystem::path to = std::filesystem::read_symlink(link, ec);
  if (ec) {
    throw Error(link.string(), "", "cannot read the symbolic link: " + ec.message());
  }
  return to.is_absolute() ? to : link.parent_path() / to;
}

}  // namespace

std::filesystem::path outputFileTarget(const std::filesystem::path& path) {
  std::filesystem::path target = path;
  for (int links = 0;; ++links) {
    struct stat st {};
    if (::lstat(target.c_str(), &st) != 0) {
      if (links == 0) {
        // A new path; a missing or unwritable folder is reported by the write itself.
        return path;
      }
      refuseTarget(path, links, target, errno == ENOENT ? "missing" : std::strerror(errno));
    }
    if (S_ISREG(st.st_mode)) {
      return target;
    }
    if (!S_ISLNK(st.st_mode)) {
      refuseTarget(path, links, target, fileKindName(st.st_mode));
    }
    if (links == kMaxLinks) {
      refuseTarget(path, links, target, "a loop of symbolic links");
    }
    target = linkTarget(target);
  }
}

void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes) {
  // Through a symbolic link the file it leads to is replaced, by a temporary file beside it
  // (the same file system, so the rename is atomic); messages name the path as given.
  const std::filesystem::path target = outputFileTarget(path);
  std::filesystem::path folder = target.parent_path();
  if (folder.empty()) {
    folder = ".";
  }
  const std::filesystem::path tmp =
      folder / ("." + target.filename().string() + ".tmp-" + std::to_string(::getpid()));
  try {
    writeTemporary(path, folder, tmp, bytes);
  } catch (...) {
    ::unlink(tmp.c_str());
    throw;
  }
  if (::rename(tmp.c_str(), target.c_str()) != 0) {
    const int error = errno;
    ::unlink(tmp.c_str());
    throw Error(path.string(), "", "cannot replace the file: " + cause(error));
  }
  // The rename is durable once the folder is synced; a folder that cannot be opened or synced
  // (some network file systems) still holds the complete file.
  const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
}

}  // namespace sonarcarve
