#include "io/files/output_folder.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>
#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

#include "common/error.h"

namespace sonarcarve {

void prepareOutputFolder(const std::filesystem::path& folder) {
  const std::string name = folder.string();
  std::error_code ec;
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
}

OutputFolderLock::OutputFolderLock(const std::filesystem::path& folder) {
  const std::filesystem::path file = folder / ".sonarcarve-lock";
  fd_ = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    throw Error(folder.string(), "",
                std::string("cannot lock the output folder: ") + std::strerror(errno));
  }
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd_);
    throw Error(folder.string(), "",
                "another run is writing in this output folder: wait for it to end or choose "
                "another one");
  }
}

OutputFolderLock::~OutputFolderLock() {
  ::close(fd_);  // releases the lock
}

}  // namespace sonarcarve
