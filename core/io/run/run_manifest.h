// The manifest of a run in its output folder (docs/formats.md, "Run manifest"): which command
// made the folder's files, when, with what result, and each file with its size and SHA-256, so that
// a folder never holds an unexplained mix of two runs. Written atomically (io/files/atomic_file.h).
//
// A run opens its manifest once its results are computed and before its first output is
// written: the manifest then says "running" and lists the earlier run's files still in the
// folder. When the run ends, complete or not, the earlier files it did not rewrite are removed
// and the manifest says "complete", "cancelled" or "failed" (with the error). A run killed
// while writing leaves "running" and the earlier files listed, which the next run removes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sonarcarve {

struct RunManifestFile {
  std::string name;  ///< in the output folder
  std::uintmax_t bytes = 0;
  std::string sha256;  ///< of its bytes as written, lowercase hex; empty if unreadable
};

class RunManifest {
 public:
  static constexpr const char* kFileName = "manifest.json";

  /// Reads the manifest of an earlier run in `folder` (if any) and lists the earlier files
  /// still there: those it names, and those of `known_outputs` present. Writes the manifest
  /// with status "running". Throws Error (the manifest's path and the cause) if it cannot be
  /// written; nothing in the folder has changed then.
  RunManifest(std::filesystem::path folder, std::vector<std::string> arguments,
              const std::vector<std::string>& known_outputs);

  /// Records a file of this run, its size and SHA-256 read from the folder.
  void wrote(const std::string& name);
  /// Records a file of this run described elsewhere (written apart, then moved in).
  void wrote(const RunManifestFile& file) { files_.push_back(file); }
  /// The files of this run recorded so far, in the order written.
  const std::vector<RunManifestFile>& files() const { return files_; }

  /// Removes the earlier files this run did not rewrite, then writes the manifest with
  /// `status` ("complete", "cancelled" or "failed") and `error` (for "failed").
  void finish(const std::string& status, const std::string& error = "");

  /// The earlier files finish() removed, as paths.
  const std::vector<std::filesystem::path>& removed() const { return removed_; }

 private:
  void write(const std::string& status, const std::string& error) const;

  std::filesystem::path folder_;
  std::vector<std::string> arguments_;
  std::string started_utc_;
  std::vector<std::string> earlier_files_;
  std::vector<RunManifestFile> files_;
  std::vector<std::filesystem::path> removed_;
};

/// The file `name` in `folder`: its size and SHA-256 (empty if it cannot be read).
RunManifestFile describeRunFile(const std::filesystem::path& folder, const std::string& name);

/// Names of the files of the earlier run listed in the manifest at `path` ("files" and, for a
/// run that did not finish, "earlier_files"); plain file names only. Empty if the manifest is
/// missing or unreadable.
std::vector<std::string> filesListedInManifest(const std::filesystem::path& path);

/// The status of the run whose manifest is in `folder` ("running", "complete", "cancelled",
/// "failed"), or nothing when there is no readable manifest (a folder of an older version).
std::optional<std::string> manifestStatus(const std::filesystem::path& folder);

}  // namespace sonarcarve
