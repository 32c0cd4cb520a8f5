#include "io/files/yaml_fields.h"

#include <charconv>
#include <cmath>
#include <map>

#include "common/angles.h"
#include "common/error.h"
#include "common/input_limits.h"
#include "io/files/input_file.h"

namespace sonarcarve {

YAML::Node YamlFields::load() const {
  return parse(readInputFile(file_, "a YAML file", kMaxYamlFileBytes));
}

YAML::Node YamlFields::parse(const std::string& text) const {
  YAML::Node root;
  try {
    root = YAML::Load(std::string(withoutByteOrderMark(text)));
  } catch (const YAML::Exception& e) {
    throw Error(file_, linePlace(e.mark.line + 1), "not valid YAML: " + e.msg);
  }
  requireUniqueKeys(root);
  return mapping(root);
}

void YamlFields::requireUniqueKeys(const YAML::Node& node, const std::string& path) const {
  if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i) {
      requireUniqueKeys(node[i], path + "[" + std::to_string(i) + "]");
    }
    return;
  }
  if (!node.IsMap()) {
    return;
  }
  std::map<std::string, int> first_line;
  for (const auto& entry : node) {
    const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : "";
    const std::string full = path.empty() ? key : path + "." + key;
    const int line = entry.first.Mark().line + 1;
    if (!key.empty()) {
      const auto [at, fresh] = first_line.emplace(key, line);
      if (!fresh) {
        throw Error(file_, linePlace(line),
                    full + ": the key appears twice (first on line " + std::to_string(at->second) +
                        "): expected each key once");
      }
    }
    requireUniqueKeys(entry.second, full);
  }
}

YAML::Node YamlFields::mapping(const YAML::Node& root) const {
  if (!root.IsMap()) {
    throw Error(file_, "", "expected a YAML mapping of keys (is the file empty?)");
  }
  return root;
}

void YamlFields::fail(const YAML::Node& node, const std::string& path,
                      const std::string& expected) const {
  const int line = node.IsDefined() ? node.Mark().line + 1 : 0;
  throw Error(file_, line > 0 ? linePlace(line) : "", path + ": " + expected);
}

YAML::Node YamlFields::child(const YAML::Node& node, const std::string& path,
                             const std::string& key) const {
  const std::string full = path.empty() ? key : path + "." + key;
  if (!node.IsMap()) {
    fail(node, path.empty() ? "document" : path, "expected a mapping with key '" + key + "'");
  }
  YAML::Node value = node[key];
  if (!value.IsDefined() || value.IsNull()) {
    fail(node, full, "missing");
  }
  return value;
}

double YamlFields::number(const YAML::Node& node, const std::string& path) const {
  double value = 0.0;
  if (!node.IsScalar() || !YAML::convert<double>::decode(node, value) || !std::isfinite(value)) {
    fail(node, path, "expected a finite number");
  }
  return value;
}

double YamlFields::positive(const YAML::Node& node, const std::string& path) const {
  const double value = number(node, path);
  if (!(value > 0.0)) {
    fail(node, path, "expected a positive number");
  }
  return value;
}

int YamlFields::positiveInt(const YAML::Node& node, const std::string& path) const {
  int value = 0;
  if (!node.IsScalar() || !YAML::convert<int>::decode(node, value) || value < 1) {
    fail(node, path, "expected a positive whole number");
  }
  return value;
}

std::string YamlFields::text(const YAML::Node& node, const std::string& path) const {
  if (!node.IsScalar()) {
    fail(node, path, "expected a text value");
  }
  return node.as<std::string>();
}

std::vector<double> YamlFields::numbers(const YAML::Node& node, const std::string& path,
                                        std::size_t size) const {
  if (!node.IsSequence() || (size > 0 && node.size() != size)) {
    fail(node, path,
         size > 0 ? "expected a list of " + std::to_string(size) + " numbers"
                  : "expected a list of numbers");
  }
  std::vector<double> values;
  for (std::size_t i = 0; i < node.size(); ++i) {
    values.push_back(number(node[i], path + "[" + std::to_string(i) + "]"));
  }
  return values;
}

}  // namespace sonarcarve

namespace sonarcarve {
std::string shortestDegrees(double angle_rad) {
  const double deg = radToDeg(angle_rad);
  // From one degree up, plain decimals ("100", not general's "1e+02"); below, general, which
  // writes tiny angles as "1e-05".
  const bool fixed = std::abs(deg) >= 1.0;
  const auto format = fixed ? std::chars_format::fixed : std::chars_format::general;
  for (int precision = fixed ? 0 : 1; precision <= 17; ++precision) {
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof(buffer), deg, format, precision);
    std::string text(buffer, result.ptr);
    double back = 0.0;
    std::from_chars(text.data(), text.data() + text.size(), back);
    if (degToRad(back) == angle_rad) {
      return text;
    }
  }
  return shortestNumber(deg);
}
}  // namespace sonarcarve
