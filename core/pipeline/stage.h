// A stage of the reconstruction pipeline: one small unit with one signature over the run's
// context (pipeline/run_context.h). Pipeline::run is one loop over its stages that handles,
// once for all of them, cancellation (a stage throws Cancelled; later stages are skipped but
// for those that finish a cancelled run), the memory each stage says it needs before it
// starts, the run's overall progress (each stage's share) and its clock.
//
// Adding a stage is one file (a class deriving from Stage) and one line (standardStages() in
// pipeline/stages/standard_stages.cpp, or Pipeline::addStage).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/progress.h"
#include "pipeline/memory_budget.h"

namespace sonarcarve {

struct RunContext;

/// What a stage will hold beyond what the run holds, checked against the run's memory
/// budget before it starts.
struct MemoryNeed {
  std::vector<MemoryPart> parts;
  std::string when;  ///< "before occlusion resolution"
};

class Stage {
 public:
  /// `name`: "read", "denoise", "carve"...; `progress_share`: its share of the run's
  /// progress, relative to the other stages' (they are summed).
  Stage(std::string name, double progress_share)
      : name_(std::move(name)), progress_share_(progress_share) {}
  virtual ~Stage() = default;
  const std::string& name() const { return name_; }
  double progressShare() const { return progress_share_; }
  /// Runs once the previous stages have; throws Cancelled when `progress` is cancelled, Error
  /// on a failure that ends the run.
  virtual void run(RunContext& run, Progress& progress) const = 0;
  /// Memory the stage will hold, checked before it runs; nullopt: nothing to check.
  virtual std::optional<MemoryNeed> memoryNeed(const RunContext& /*run*/) const {
    return std::nullopt;
  }
  /// Whether it still runs after an earlier stage was cancelled (to finish what a cancelled
  /// run leaves: its report and outputs).
  virtual bool runsAfterCancel() const { return false; }

 private:
  std::string name_;
  double progress_share_;
};

}  // namespace sonarcarve
