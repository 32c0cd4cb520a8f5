#include "common/available_memory.h"

#include <cstdlib>

#include "common/proc_text.h"

namespace sonarcarve {
namespace {

void keepSmaller(std::optional<AvailableMemory>& best, std::optional<std::uint64_t> bytes,
                 const std::string& source) {
  if (bytes && (!best || *bytes < best->bytes)) {
    best = AvailableMemory{*bytes, source};
  }
}

}  // namespace

std::optional<AvailableMemory> availableMemoryFrom(const std::string& meminfo,
                                                   const std::string& cgroup_max,
                                                   const std::string& cgroup_current,
                                                   const std::string& user_limit_mb) {
  std::optional<AvailableMemory> best;
  keepSmaller(best, procKibField(meminfo, "MemAvailable:"), "MemAvailable in /proc/meminfo");
  const auto max = wholeNumberOf(cgroup_max);  // "max" (no limit) is not a number
  const auto current = wholeNumberOf(cgroup_current);
  if (max && current) {
    keepSmaller(best, *max > *current ? *max - *current : 0,
                "the container's memory limit (cgroup memory.max)");
  }
  const auto user_mb = wholeNumberOf(user_limit_mb);
  if (user_mb) {
    keepSmaller(best, *user_mb * 1024 * 1024, "SONARCARVE_MEMORY_LIMIT_MB");
  }
  return best;
}

std::optional<AvailableMemory> availableMemory() {
  const char* user = std::getenv("SONARCARVE_MEMORY_LIMIT_MB");
  return availableMemoryFrom(procFileText("/proc/meminfo"),
                             procFileText("/sys/fs/cgroup/memory.max"),
                             procFileText("/sys/fs/cgroup/memory.current"), user ? user : "");
}

}  // namespace sonarcarve
