#include "io/files/json_text.h"

#include <nlohmann/json.hpp>

namespace sonarcarve {

std::string jsonText(const nlohmann::json& value, int indent) {
  return value.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace sonarcarve
