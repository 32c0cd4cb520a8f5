// sonarcarve::Error: the one exception type of the engine.
// Every error names where it happened (a file, or a component such as "navigation"),
// the place inside it (a line, a frame, a byte offset, a time) and what was expected,
// so a user can find and fix the input without reading the code.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace sonarcarve {

class Error : public std::runtime_error {
 public:
  /// `source`: file path or component; `place`: "line 12", "frame 3", "byte 1024" or "".
  Error(std::string source, std::string place, std::string message);

  const std::string& source() const { return source_; }
  const std::string& place() const { return place_; }
  const std::string& message() const { return message_; }

 private:
  std::string source_;
  std::string place_;
  std::string message_;
};

/// "line N" as used in Error places.
std::string linePlace(int line);
/// "byte N" (offset from the start of the file) as used in Error places of binary readers.
std::string bytePlace(std::size_t offset);

}  // namespace sonarcarve
