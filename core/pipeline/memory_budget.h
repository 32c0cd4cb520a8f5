// A run's memory budget (issue 18): the user's memory_budget_mb, or a share of the memory
// available when the run starts. The pipeline checks it where memory grows: before the map is
// allocated (size_limits.h), after each carved frame, and before occlusion resolution and the
// mesh, so that a mission too large for the machine stops between frames with an Error that
// gives the figures, instead of swapping or being killed. A run that lets finished blocks go
// (evict_blocks) releases them after each frame before the check, so the check sees what is
// left; past the budget then the run stops (docs/reliability.md, "Limits").
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "common/available_memory.h"

namespace sonarcarve {

/// The share of the memory available that a run takes by default. The rest is for what the
/// checks do not count (allocator slack, the workbench's views of the map) and for what the
/// machine needs meanwhile: other programs growing during a long run, the kernel's caches.
inline constexpr double kDefaultMemoryShare = 0.8;

struct MemoryBudget {
  std::uint64_t bytes = 0;
  /// Where the figure comes from, for messages: "memory_budget_mb", or "80 % of 3.7 GiB
  /// available, MemAvailable in /proc/meminfo".
  std::string origin;
};

/// `budget_mb` MiB when it is not 0, else kDefaultMemoryShare of `available`; nullopt when
/// neither is known (nothing is checked then).
std::optional<MemoryBudget> memoryBudget(std::uint64_t budget_mb,
                                         const std::optional<AvailableMemory>& available);

/// "0.8 MiB", "812 MiB", "3.2 GiB".
std::string memoryFigure(double bytes);

/// A part of what a run holds, named in messages.
struct MemoryPart {
  std::string what;  ///< "map", "frame buffers of 2 threads"
  double bytes = 0.0;
};

/// Checks one run against its budget by two measures: what the run counts (the map's own
/// figure and estimates of the other stages' buffers), and how much the process's resident
/// memory has grown since the watch began, which also sees what nothing counts.
class MemoryWatch {
 public:
  using ResidentMemory = std::function<std::optional<std::uint64_t>()>;

  /// Reads the resident memory now (through `resident`, the VmRSS of processMemory() by default) as
  /// the run's starting point.
  explicit MemoryWatch(std::optional<MemoryBudget> budget, ResidentMemory resident = {});

  const std::optional<MemoryBudget>& budget() const { return budget_; }

  /// Throws Error("parameters", "memory_budget_mb", ...) when the sum of `parts` or the
  /// growth of resident memory exceeds the budget. `when` says where the run is: "after frame
  /// 812 of 36000", "before occlusion resolution".
  void require(const std::vector<MemoryPart>& parts, const std::string& when) const;

 private:
  std::optional<MemoryBudget> budget_;
  ResidentMemory resident_;
  std::optional<std::uint64_t> resident_at_start_;
};

}  // namespace sonarcarve
