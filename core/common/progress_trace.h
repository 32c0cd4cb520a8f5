// MemoryTrace: a Progress that passes every report and the cancellation on to another one and
// keeps a trace of the run beside it: when each stage ended, and the process's memory
// (common/process_memory.h) at each change of stage, at the end of each stage and every
// `every` units of work within one, against the frames carved so far. For benchmarks of whole
// runs (`sonarcarve-cli bench reconstruct`). Thread safe, as Progress must be.
#pragma once

#include <chrono>
#include <mutex>
#include <string>
#include <vector>

#include "common/process_memory.h"
#include "common/progress.h"

namespace sonarcarve {

struct MemorySample {
  double time_s = 0.0;  ///< since the trace started
  std::string stage;
  std::size_t done = 0;  ///< of the stage's units
  std::size_t total = 0;
  std::size_t frames_carved = 0;  ///< the carving stage's progress so far
  ProcessMemory memory;
};

struct StageSpan {
  std::string stage;
  double first_report_s = 0.0;
  double last_report_s = 0.0;
  std::size_t units = 0;  ///< the stage's total at its last report
};

class MemoryTrace : public Progress {
 public:
  /// Reports go on to `inner`; `frame_stage` names the stage whose units are frames carved.
  explicit MemoryTrace(Progress& inner, std::size_t every = 100, std::string frame_stage = "carve");
  void report(const std::string& stage, std::size_t done, std::size_t total) override;
  bool cancelled() const override { return inner_.cancelled(); }

  /// A sample now, under `stage` (e.g. "start", "end").
  void sample(const std::string& stage);
  double elapsedSeconds() const;
  std::vector<MemorySample> samples() const;
  /// The stages in the order they first reported.
  std::vector<StageSpan> stages() const;

 private:
  void sampleLocked(const std::string& stage, std::size_t done, std::size_t total);

  Progress& inner_;
  std::size_t every_;
  std::string frame_stage_;
  std::chrono::steady_clock::time_point start_;
  mutable std::mutex mutex_;
  std::vector<MemorySample> samples_;
  std::vector<StageSpan> stages_;
  std::size_t frames_carved_ = 0;
  std::size_t next_sample_ = 0;  // units of the current stage at which to sample next
};

}  // namespace sonarcarve
