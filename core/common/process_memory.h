// This process's memory as Linux counts it in /proc/self/status: resident now (VmRSS), the
// most resident so far (VmHWM, the peak), and the anonymous part of the resident memory
// (RssAnon: the heap and other allocations, without the program's mapped files).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace sonarcarve {

struct ProcessMemory {
  std::uint64_t resident_bytes = 0;       ///< VmRSS
  std::uint64_t peak_resident_bytes = 0;  ///< VmHWM
  std::uint64_t anonymous_bytes = 0;      ///< RssAnon
};

/// Reads /proc/self/status; nothing where it cannot be read (not Linux).
std::optional<ProcessMemory> processMemory();
/// The same from the text of a status file; nothing unless VmRSS and VmHWM are in it (RssAnon,
/// missing before Linux 4.5, is then 0).
std::optional<ProcessMemory> processMemoryFrom(const std::string& status);

/// Bytes in MB (10^6 bytes), as the benchmarks quote them.
inline double megabytes(std::uint64_t bytes) {
  return static_cast<double>(bytes) / 1e6;
}

}  // namespace sonarcarve
