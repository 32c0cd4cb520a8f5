// The folder a command writes into, made ready before any work starts, so that a run of
// minutes does not end in an error about its output.
#pragma once

#include <filesystem>

namespace sonarcarve {

/// Creates `folder` (and its parents) if needed and checks that files can be created in it.
/// Throws Error naming the folder and the cause: a regular file in the way, a read-only
/// folder or disk, a missing permission.
void prepareOutputFolder(const std::filesystem::path& folder);

/// A run's exclusive hold on its output folder: an advisory lock on FOLDER/.sonarcarve-lock,
/// released when the object dies or the process ends, even by a kill. A second run into the
/// same folder fails at once, naming it, instead of interleaving its files with the first's.
class OutputFolderLock {
 public:
  explicit OutputFolderLock(const std::filesystem::path& folder);
  ~OutputFolderLock();
  OutputFolderLock(const OutputFolderLock&) = delete;
  OutputFolderLock& operator=(const OutputFolderLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace sonarcarve
