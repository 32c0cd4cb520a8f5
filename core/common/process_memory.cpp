#include "common/process_memory.h"

#include "common/proc_text.h"

namespace sonarcarve {

std::optional<ProcessMemory> processMemoryFrom(const std::string& status) {
  const auto resident = procKibField(status, "VmRSS:");
  const auto peak = procKibField(status, "VmHWM:");
  if (!resident || !peak) {
    return std::nullopt;
  }
  return ProcessMemory{*resident, *peak, procKibField(status, "RssAnon:").value_or(0)};
}

std::optional<ProcessMemory> processMemory() {
  return processMemoryFrom(procFileText("/proc/self/status"));
}

}  // namespace sonarcarve
