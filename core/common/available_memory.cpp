#include "common/available_memory.h"

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace sonarcarve {
namespace {

std::string fileText(const char* path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::optional<std::uint64_t> wholeNumber(const std::string& text) {
  std::istringstream in(text);
  std::uint64_t value = 0;
  if (!(in >> value)) {
    return std::nullopt;
  }
  return value;
}

// "MemAvailable:   1234 kB" in /proc/meminfo.
std::optional<std::uint64_t> memAvailableBytes(const std::string& meminfo) {
  const std::string key = "MemAvailable:";
  const auto at = meminfo.find(key);
  if (at == std::string::npos) {
    return std::nullopt;
  }
  const auto kib = wholeNumber(meminfo.substr(at + key.size()));
  return kib ? std::optional<std::uint64_t>(*kib * 1024) : std::nullopt;
}

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
  keepSmaller(best, memAvailableBytes(meminfo), "MemAvailable in /proc/meminfo");
  const auto max = wholeNumber(cgroup_max);  // "max" (no limit) is not a number
  const auto current = wholeNumber(cgroup_current);
  if (max && current) {
    keepSmaller(best, *max > *current ? *max - *current : 0,
                "the container's memory limit (cgroup memory.max)");
  }
  const auto user_mb = wholeNumber(user_limit_mb);
  if (user_mb) {
    keepSmaller(best, *user_mb * 1024 * 1024, "SONARCARVE_MEMORY_LIMIT_MB");
  }
  return best;
}

std::optional<AvailableMemory> availableMemory() {
  const char* user = std::getenv("SONARCARVE_MEMORY_LIMIT_MB");
  return availableMemoryFrom(fileText("/proc/meminfo"), fileText("/sys/fs/cgroup/memory.max"),
                             fileText("/sys/fs/cgroup/memory.current"), user ? user : "");
}

}  // namespace sonarcarve
