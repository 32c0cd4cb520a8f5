// The folder a command writes into, made ready before any work starts, so that a run of
// minutes does not end in an error about its output, and held so that two runs do not mix
// their files in it.
#pragma once

#include <filesystem>
#include <memory>
#include <vector>

namespace sonarcarve {

/// Throws Error naming `folder` unless it is a folder (or a symbolic link to one) or a new
/// path: a regular file, a FIFO, a device or a socket in the way is refused by name ("is a
/// FIFO (named pipe): expected a folder or a new path"), as is a link that leads nowhere.
/// Nothing is created: commands call it on their --out before any work.
void requireOutputFolder(const std::filesystem::path& folder);

/// Checks `folder` as requireOutputFolder, creates it (and its parents) if needed and checks
/// that files can be created in it. Throws Error naming the folder and the cause: something
/// else in the way, a read-only folder or disk, a missing permission. Returns the folders it
/// created, outermost first (none when `folder` existed), for removeCreatedFolders.
std::vector<std::filesystem::path> prepareOutputFolder(const std::filesystem::path& folder);

/// What a run that failed does with the folders prepareOutputFolder created for it, so that no
/// folder is left that looks like a result: removes them, innermost first, if they are empty,
/// or, with `with_contents` (a command whose partial output is no result: simulate, import),
/// with what is in them. Stops at the first that cannot or must not be removed. Returns those
/// removed; never throws.
std::vector<std::filesystem::path> removeCreatedFolders(
    const std::vector<std::filesystem::path>& created, bool with_contents);

enum class FolderUse {
  Exclusive,  ///< a run that writes the folder's files (simulate, import, reconstruct)
  Shared,     ///< a command that writes one file into it (export, noise-model): several may
};

/// A command's hold on its output folder: an advisory lock (flock) on the folder itself, which
/// leaves no file behind and is released when the object dies or the process ends, even by a
/// kill. A run holds its folder exclusively; a command writing one file into a folder shares it
/// with others of its kind. A command that cannot have its hold fails at once, naming the
/// folder and the process that holds it, instead of interleaving its files with the other's:
/// "out: is being written by another sonarcarve run (pid 1234)". On a file system without
/// locks (some network ones) the command runs without a hold (held() is false).
class OutputFolderLock {
 public:
  /// `folder` must exist (prepareOutputFolder).
  explicit OutputFolderLock(const std::filesystem::path& folder,
                            FolderUse use = FolderUse::Exclusive);
  ~OutputFolderLock();
  OutputFolderLock(const OutputFolderLock&) = delete;
  OutputFolderLock& operator=(const OutputFolderLock&) = delete;

  bool held() const { return fd_ >= 0; }

 private:
  int fd_ = -1;
};

/// For a command that writes one file (export, noise-model): checks `file` before any work as
/// the writer will (outputFileTarget in io/files/atomic_file.h: a FIFO, a device, a folder in
/// the way are refused), checks that the folder it goes into exists, and returns a shared hold
/// on that folder, to keep while the command runs.
std::unique_ptr<OutputFolderLock> holdOutputFile(const std::filesystem::path& file);

}  // namespace sonarcarve
