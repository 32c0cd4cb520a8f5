#include "io/run/staged_outputs.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>
#include <cerrno>
#include <cstring>
#include <system_error>

#include "common/error.h"
#include "common/input_limits.h"
#include "io/files/atomic_file.h"
#include "io/files/input_file.h"

namespace sonarcarve {
namespace {

// Whether a staging folder's name (".run.tmp-PID") is that of a process that is gone.
bool leftByAGoneProcess(const std::string& name) {
  const std::string prefix = StagedOutputs::kPrefix;
  if (name.rfind(prefix, 0) != 0) {
    return false;
  }
  const std::string digits = name.substr(prefix.size());
  if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos ||
      digits.size() > 9) {
    return false;
  }
  const pid_t pid = static_cast<pid_t>(std::stol(digits));
  return pid != ::getpid() && ::kill(pid, 0) != 0 && errno == ESRCH;
}

void removeStagingLeftByKilledRuns(const std::filesystem::path& folder) {
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    std::error_code kind;
    if (entry.is_directory(kind) && !entry.is_symlink(kind) &&
        leftByAGoneProcess(entry.path().filename().string())) {
      std::filesystem::remove_all(entry.path(), kind);
    }
  }
}

// Renames `from` to `to`, or throws Error naming `output` and the cause.
void move(const std::filesystem::path& from, const std::filesystem::path& to,
          const std::filesystem::path& output) {
  if (::rename(from.c_str(), to.c_str()) != 0) {
    throw Error(output.string(), "",
                std::string("cannot move the run's files into place: ") + std::strerror(errno));
  }
}

}  // namespace

StagedOutputs::StagedOutputs(std::filesystem::path folder)
    : folder_(std::move(folder)),
      staging_(folder_ / (std::string(kPrefix) + std::to_string(::getpid()))) {
  removeStagingLeftByKilledRuns(folder_);
  std::error_code ec;
  std::filesystem::remove_all(staging_, ec);  // this process's own, from an earlier run
  if (!std::filesystem::create_directory(staging_, ec)) {
    throw Error(staging_.string(), "",
                "cannot create the folder the run's outputs are written in first" +
                    (ec ? ": " + ec.message() : std::string()) +
                    ": expected a folder where files can be created");
  }
}

StagedOutputs::~StagedOutputs() {
  std::error_code ec;
  std::filesystem::remove_all(staging_, ec);
}

void StagedOutputs::publish(const std::string& name) const {
  const std::filesystem::path output = folder_ / name;
  const std::filesystem::path target = outputFileTarget(output);
  const std::filesystem::path staged = staging_ / name;
  if (::rename(staged.c_str(), target.c_str()) == 0) {
    return;
  }
  if (errno != EXDEV) {
    throw Error(output.string(), "",
                std::string("cannot move the run's file into place: ") + std::strerror(errno));
  }
  // A link leading to another file system: its target is rewritten there, atomically.
  writeFileAtomically(output, readInputFile(staged, "a staged output", kMaxMapFileBytes));
}

void StagedOutputs::requireTarget(const std::string& name) const {
  const std::filesystem::path output = folder_ / name;
  std::error_code ec;
  if (!std::filesystem::is_directory(staging_ / name, ec)) {
    outputFileTarget(output);
    return;
  }
  const std::filesystem::file_type kind = std::filesystem::symlink_status(output, ec).type();
  if (kind != std::filesystem::file_type::directory &&
      kind != std::filesystem::file_type::not_found) {
    throw Error(output.string(), "",
                "is not a folder: expected a folder or a new path, to move the run's " + name +
                    " folder in");
  }
}

void StagedOutputs::publishFolder(const std::string& name) const {
  requireTarget(name);
  const std::filesystem::path output = folder_ / name;
  const std::filesystem::path earlier = staging_ / (".earlier-" + name);
  std::error_code ec;
  const bool replaces = std::filesystem::is_directory(std::filesystem::symlink_status(output, ec));
  if (replaces) {
    move(output, earlier, output);
  }
  try {
    move(staging_ / name, output, output);
  } catch (const Error&) {
    if (replaces) {
      ::rename(earlier.c_str(), output.c_str());  // the earlier folder back in place
    }
    throw;
  }
}

void StagedOutputs::sync() const {
  const int fd = ::open(folder_.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
}

std::string StagedOutputs::outputName(const std::string& path) const {
  const std::string staging = staging_.string();
  if (path.rfind(staging, 0) != 0) {
    return path;
  }
  return (folder_ / path.substr(staging.size() + (path.size() > staging.size() ? 1 : 0))).string();
}

Error StagedOutputs::nothingChanged(const Error& e) const {
  return Error(outputName(e.source()), e.place(),
               e.message() + "; nothing was changed in " + folder_.string() +
                   " (the run's files are written apart first and moved in when all are "
                   "complete)");
}

}  // namespace sonarcarve
