#include "io/files/output_folder.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <system_error>

#include "common/error.h"
#include "io/files/atomic_file.h"
#include "io/files/file_kind.h"

namespace sonarcarve {
namespace {

// The process holding a lock on the file `st` describes, from /proc/locks (Linux): lines such
// as "1: FLOCK  ADVISORY  WRITE 1234 fe:00:5678 0 EOF" (device in hex, inode in decimal).
std::optional<long> lockHolder(const struct stat& st) {
  char inode[64];
  std::snprintf(inode, sizeof inode, "%02x:%02x:%lu", major(st.st_dev), minor(st.st_dev),
                static_cast<unsigned long>(st.st_ino));
  std::ifstream locks("/proc/locks");
  std::string line;
  while (std::getline(locks, line)) {
    std::istringstream fields(line);
    std::string id, type, advisory, mode, file;
    long pid = 0;
    if (fields >> id >> type >> advisory >> mode >> pid >> file && type != "->" && file == inode) {
      return pid;
    }
  }
  return std::nullopt;
}

}  // namespace

void requireOutputFolder(const std::filesystem::path& folder) {
  struct stat st {};
  if (::stat(folder.c_str(), &st) == 0) {
    if (!S_ISDIR(st.st_mode)) {
      throw Error(folder.string(), "",
                  "is " + fileKindName(st.st_mode) + ": expected a folder or a new path");
    }
  } else if (errno == ENOENT && ::lstat(folder.c_str(), &st) == 0) {
    throw Error(folder.string(), "",
                "is a symbolic link that leads nowhere: expected a folder or a new path");
  }
  // Anything else (a missing permission, a file among the parents) is for the creation to say.
}

std::vector<std::filesystem::path> prepareOutputFolder(const std::filesystem::path& folder) {
  requireOutputFolder(folder);
  const std::string name = folder.string();
  std::vector<std::filesystem::path> created;
  std::error_code ec;
  for (std::filesystem::path missing = folder;
       !missing.empty() && !std::filesystem::exists(std::filesystem::symlink_status(missing, ec));
       missing = missing.parent_path()) {
    created.push_back(missing);
    if (missing == missing.parent_path()) {
      break;
    }
  }
  std::reverse(created.begin(), created.end());  // outermost first
  std::filesystem::create_directories(folder, ec);
  if (ec || !std::filesystem::is_directory(folder)) {
    throw Error(name, "",
                "cannot create the output folder" + (ec ? ": " + ec.message() : std::string()) +
                    ": expected a folder, or a path where one can be made");
  }
  // Permissions alone do not say it (root writes anywhere, except on a read-only disk): create
  // a file and remove it.
  const std::filesystem::path probe = folder / (".write-test-" + std::to_string(::getpid()));
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) {
    throw Error(name, "",
                std::string("cannot write in the output folder: ") + std::strerror(errno) +
                    ": expected a folder where files can be created");
  }
  ::close(fd);
  ::unlink(probe.c_str());
  return created;
}

std::vector<std::filesystem::path> removeCreatedFolders(
    const std::vector<std::filesystem::path>& created, bool with_contents) {
  std::vector<std::filesystem::path> removed;
  for (auto folder = created.rbegin(); folder != created.rend(); ++folder) {
    std::error_code ec;
    const bool inner = folder == created.rbegin();
    if (inner && with_contents) {
      std::filesystem::remove_all(*folder, ec);
    } else {
      std::filesystem::remove(*folder, ec);  // only if empty
    }
    if (ec || std::filesystem::exists(std::filesystem::symlink_status(*folder, ec))) {
      break;
    }
    removed.push_back(*folder);
  }
  return removed;
}

OutputFolderLock::OutputFolderLock(const std::filesystem::path& folder, FolderUse use) {
  const std::filesystem::path path = folder.empty() ? "." : folder;
  // A lock on the folder itself: no file is left in it to list, compare or remove.
  fd_ = ::open(path.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd_ < 0) {
    throw Error(path.string(), "",
                std::string("cannot lock the output folder: ") + std::strerror(errno));
  }
  const int operation = (use == FolderUse::Exclusive ? LOCK_EX : LOCK_SH) | LOCK_NB;
  int result = 0;
  do {
    result = ::flock(fd_, operation);
  } while (result != 0 && errno == EINTR);
  if (result == 0) {
    return;
  }
  const int error = errno;
  struct stat st {};
  const bool known = ::fstat(fd_, &st) == 0;
  ::close(fd_);
  fd_ = -1;
  if (error != EWOULDBLOCK) {
    return;  // a file system without flock: no hold, as held() says
  }
  const std::optional<long> pid = known ? lockHolder(st) : std::nullopt;
  throw Error(path.string(), "",
              "is being written by another sonarcarve run" +
                  (pid ? " (pid " + std::to_string(*pid) + ")" : std::string()) +
                  ": wait for it to end or choose another folder");
}

OutputFolderLock::~OutputFolderLock() {
  if (fd_ >= 0) {
    ::close(fd_);  // releases the lock
  }
}

std::unique_ptr<OutputFolderLock> holdOutputFile(const std::filesystem::path& file) {
  const std::filesystem::path target = outputFileTarget(file);
  const std::filesystem::path folder =
      target.parent_path().empty() ? std::filesystem::path(".") : target.parent_path();
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) {
    // As the writer would say it, at the end of the work.
    throw Error(file.string(), "",
                "cannot create a file in " + folder.string() + ": " +
                    std::make_error_code(std::errc::no_such_file_or_directory).message());
  }
  return std::make_unique<OutputFolderLock>(folder, FolderUse::Shared);
}

}  // namespace sonarcarve
