#include "common/proc_text.h"

#include <fstream>
#include <sstream>

namespace sonarcarve {

std::string procFileText(const char* path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::optional<std::uint64_t> wholeNumberOf(const std::string& text) {
  std::istringstream in(text);
  std::uint64_t value = 0;
  if (!(in >> value)) {
    return std::nullopt;
  }
  return value;
}

std::optional<std::uint64_t> procKibField(const std::string& text, const std::string& key) {
  for (std::size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + 1)) {
    if (at == 0 || text[at - 1] == '\n') {
      const std::size_t end = text.find('\n', at);
      const auto kib = wholeNumberOf(text.substr(at + key.size(), end - at - key.size()));
      return kib ? std::optional<std::uint64_t>(*kib * 1024) : std::nullopt;
    }
  }
  return std::nullopt;
}

}  // namespace sonarcarve
