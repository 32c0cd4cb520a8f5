// The resident memory of this process (VmRSS in /proc/self/status): what it really holds in
// RAM, including what no counter of the engine sees (allocator slack, a viewer's copies).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace sonarcarve {

/// VmRSS of this process in bytes; nullopt where /proc/self/status does not give it.
std::optional<std::uint64_t> residentMemory();

/// The same from the text of a /proc/PID/status file, for tests.
std::optional<std::uint64_t> residentMemoryFrom(const std::string& status);

}  // namespace sonarcarve
