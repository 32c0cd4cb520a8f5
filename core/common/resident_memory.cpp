#include "common/resident_memory.h"

#include <fstream>
#include <sstream>

namespace sonarcarve {

std::optional<std::uint64_t> residentMemoryFrom(const std::string& status) {
  const std::string key = "VmRSS:";
  const auto at = status.find(key);
  if (at == std::string::npos) {
    return std::nullopt;
  }
  std::istringstream in(status.substr(at + key.size()));
  std::uint64_t kib = 0;
  if (!(in >> kib)) {
    return std::nullopt;
  }
  return kib * 1024;
}

std::optional<std::uint64_t> residentMemory() {
  std::ifstream in("/proc/self/status");
  std::stringstream text;
  text << in.rdbuf();
  return residentMemoryFrom(text.str());
}

}  // namespace sonarcarve
