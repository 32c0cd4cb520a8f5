#include "io/files/yaml_block_keys.h"

#include <cctype>
#include <map>
#include <vector>

#include "common/error.h"

namespace sonarcarve {
namespace {

struct BlockKey {
  std::size_t indent = 0;
  std::string key;
};

// "   rows: 200" -> {3, "rows"}; nothing for a line that does not start with a plain key.
bool blockKeyOf(std::string_view line, BlockKey& found) {
  std::size_t at = 0;
  while (at < line.size() && line[at] == ' ') {
    ++at;
  }
  const std::size_t start = at;
  while (at < line.size() && (std::isalnum(static_cast<unsigned char>(line[at])) != 0 ||
                              line[at] == '_' || line[at] == '-' || line[at] == '.')) {
    ++at;
  }
  const bool key_end = at < line.size() && line[at] == ':' &&
                       (at + 1 == line.size() || line[at + 1] == ' ' || line[at + 1] == '\r');
  if (at == start || !key_end || std::isalpha(static_cast<unsigned char>(line[start])) == 0) {
    return false;
  }
  found = {start, std::string(line.substr(start, at - start))};
  return true;
}

struct Scope {
  std::size_t indent = 0;
  std::map<std::string, int> first_line;
};

}  // namespace

void requireUniqueBlockKeys(std::string_view text, const std::string& file) {
  std::vector<Scope> scopes;
  int line_number = 0;
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    const std::string_view line = text.substr(0, end);
    text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
    ++line_number;
    BlockKey key;
    if (!blockKeyOf(line, key)) {
      continue;
    }
    while (!scopes.empty() && scopes.back().indent > key.indent) {
      scopes.pop_back();
    }
    if (scopes.empty() || scopes.back().indent < key.indent) {
      scopes.push_back({key.indent, {}});
    }
    const auto [at, fresh] = scopes.back().first_line.emplace(key.key, line_number);
    if (!fresh) {
      throw Error(file, linePlace(line_number),
                  key.key + ": the key appears twice (first on line " + std::to_string(at->second) +
                      "): expected each key once");
    }
  }
}

}  // namespace sonarcarve
