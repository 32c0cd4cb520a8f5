#include "pipeline/memory_budget.h"

#include <cmath>
#include <sstream>

#include "common/error.h"
#include "common/process_memory.h"

namespace sonarcarve {
namespace {

constexpr double kMiB = 1024.0 * 1024.0;
constexpr double kGiB = 1024.0 * kMiB;

std::string fixed(double value, int decimals) {
  std::ostringstream text;
  text.setf(std::ios::fixed);
  text.precision(decimals);
  text << value;
  return text.str();
}

std::string partsText(const std::vector<MemoryPart>& parts) {
  std::string text;
  for (const MemoryPart& part : parts) {
    text += (text.empty() ? "" : ", ") + part.what + " " + memoryFigure(part.bytes);
  }
  return text;
}

}  // namespace

std::optional<MemoryBudget> memoryBudget(std::uint64_t budget_mb,
                                         const std::optional<AvailableMemory>& available) {
  if (budget_mb > 0) {
    return MemoryBudget{budget_mb * 1024 * 1024, "memory_budget_mb"};
  }
  if (!available) {
    return std::nullopt;
  }
  const double share = kDefaultMemoryShare * static_cast<double>(available->bytes);
  return MemoryBudget{static_cast<std::uint64_t>(share),
                      fixed(kDefaultMemoryShare * 100.0, 0) + " % of " +
                          memoryFigure(static_cast<double>(available->bytes)) + " available, " +
                          available->source};
}

std::string memoryFigure(double bytes) {
  if (bytes >= kGiB) {
    return fixed(bytes / kGiB, 1) + " GiB";
  }
  if (bytes >= 10.0 * kMiB) {
    return fixed(bytes / kMiB, 0) + " MiB";
  }
  return fixed(bytes / kMiB, 1) + " MiB";
}

MemoryWatch::MemoryWatch(std::optional<MemoryBudget> budget, ResidentMemory resident)
    : budget_(std::move(budget)),
      resident_(resident ? std::move(resident)
                         : ResidentMemory([]() -> std::optional<std::uint64_t> {
                             const auto memory = processMemory();
                             return memory ? std::optional(memory->resident_bytes) : std::nullopt;
                           })),
      resident_at_start_(budget_ ? resident_() : std::nullopt) {}

void MemoryWatch::require(const std::vector<MemoryPart>& parts, const std::string& when) const {
  if (!budget_) {
    return;
  }
  double counted = 0.0;
  for (const MemoryPart& part : parts) {
    counted += part.bytes;
  }
  double grown = 0.0;
  if (resident_at_start_) {
    if (const auto now = resident_()) {
      grown = *now > *resident_at_start_ ? static_cast<double>(*now - *resident_at_start_) : 0.0;
    }
  }
  const auto budget = static_cast<double>(budget_->bytes);
  if (counted <= budget && grown <= budget) {
    return;
  }
  std::ostringstream text;
  if (counted > budget) {
    text << "the run holds " << memoryFigure(counted) << " " << when << " (" << partsText(parts)
         << ")";
  } else {
    text << "the process has grown by " << memoryFigure(grown) << " since the run began, " << when
         << " (the run counts " << memoryFigure(counted) << ": " << partsText(parts) << ")";
  }
  text << ", over the memory budget of " << memoryFigure(budget) << " (" << budget_->origin
       << "): set memory_budget_mb, a region of interest (region), a larger voxel size "
          "(voxel_size_m), or shard the mission (docs/scaling.md)";
  throw Error("parameters", "memory_budget_mb", text.str());
}

}  // namespace sonarcarve
