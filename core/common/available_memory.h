// How much memory a run may still take, so that sizes derived from input and parameters are
// checked against the machine before they are allocated (docs/reliability.md, "Limits").
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace sonarcarve {

struct AvailableMemory {
  std::uint64_t bytes = 0;
  std::string source;  ///< where the figure comes from, for messages
};

/// The smallest of: MemAvailable in /proc/meminfo; the room left under a cgroup v2 memory
/// limit (memory.max minus memory.current, as in a container); and the environment variable
/// SONARCARVE_MEMORY_LIMIT_MB, a user's own cap. nullopt if none is known.
std::optional<AvailableMemory> availableMemory();

/// The same from given texts (empty: not known), for tests: the contents of /proc/meminfo,
/// memory.max, memory.current and the environment variable.
std::optional<AvailableMemory> availableMemoryFrom(const std::string& meminfo,
                                                   const std::string& cgroup_max,
                                                   const std::string& cgroup_current,
                                                   const std::string& user_limit_mb);

}  // namespace sonarcarve
