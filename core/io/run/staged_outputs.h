// A run's outputs are written apart first, into a staging folder inside the output folder
// (".run.tmp-PID"), and moved into the output folder by rename only once every one of them is
// complete. A run that fails while writing (a full disk) then leaves the output folder as it
// was, an earlier run's results included. Inside rather than beside the output folder: the
// renames stay on one file system (an --out that is a mount point), the folder is already
// known to be writable, and the run's lock on it (io/files/output_folder.h) covers both.
#pragma once

#include <filesystem>
#include <string>

#include "common/error.h"

namespace sonarcarve {

class StagedOutputs {
 public:
  static constexpr const char* kPrefix = ".run.tmp-";

  /// Makes this run's staging folder in `folder`, and removes those of runs that were killed
  /// (their process is gone). Throws Error naming the staging folder if it cannot be made.
  explicit StagedOutputs(std::filesystem::path folder);
  /// Removes the staging folder and whatever was not moved out of it.
  ~StagedOutputs();
  StagedOutputs(const StagedOutputs&) = delete;
  StagedOutputs& operator=(const StagedOutputs&) = delete;

  const std::filesystem::path& folder() const { return folder_; }
  const std::filesystem::path& staging() const { return staging_; }

  /// Moves `name` from the staging folder into the output folder, onto
  /// outputFileTarget(folder / name) (io/files/atomic_file.h: a link is written through, a FIFO
  /// or a device refused). Throws Error naming the output file and the cause.
  void publish(const std::string& name) const;

  /// Throws Error, as publish or publishFolder would, if what is at `name` in the output folder
  /// cannot be replaced by the staged `name` (a FIFO where a file goes, a file where a folder
  /// goes); changes nothing.
  void requireTarget(const std::string& name) const;

  /// Moves the staged folder `name` into the output folder. A folder of that name there (an
  /// earlier run's) is first moved into the staging folder and goes with it; anything else in
  /// the way (a file, a link) is refused. Throws Error naming the output folder's `name`.
  void publishFolder(const std::string& name) const;

  /// Syncs the output folder, so that the renames survive a power cut.
  void sync() const;

  /// `path` with the staging folder replaced by the output folder: what a message should name.
  std::string outputName(const std::string& path) const;

  /// `e`, raised while the run wrote into the staging folder, as a message on the output
  /// folder: the file named there (outputName), and saying that nothing was changed in it.
  Error nothingChanged(const Error& e) const;

 private:
  std::filesystem::path folder_;
  std::filesystem::path staging_;
};

}  // namespace sonarcarve
