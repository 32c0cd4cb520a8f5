#include "common/error.h"

namespace sonarcarve {
namespace {
std::string compose(const std::string& source, const std::string& place,
                    const std::string& message) {
  std::string text = source;
  if (!place.empty()) {
    text += ": " + place;
  }
  return text + ": " + message;
}
}  // namespace

Error::Error(std::string source, std::string place, std::string message)
    : std::runtime_error(compose(source, place, message)),
      source_(std::move(source)),
      place_(std::move(place)),
      message_(std::move(message)) {}

std::string linePlace(int line) {
  return "line " + std::to_string(line);
}

std::string bytePlace(std::size_t offset) {
  return "byte " + std::to_string(offset);
}

}  // namespace sonarcarve
