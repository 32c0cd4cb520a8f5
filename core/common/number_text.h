// Numbers as text for files and messages.
#pragma once

#include <charconv>
#include <string>

namespace sonarcarve {

/// The shortest text that reads back as exactly `value` ("0.02", not "0.0200000000000000004").
inline std::string shortestNumber(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

}  // namespace sonarcarve
