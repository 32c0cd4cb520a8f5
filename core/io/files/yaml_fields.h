// Reading typed fields out of a YAML document with errors that name the file, the line and
// the key, e.g. "mission.yaml: line 7: sonar.range.resolution_m: expected a positive number".
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>
#include "common/number_text.h"

namespace sonarcarve {

class YamlFields {
 public:
  explicit YamlFields(std::string file) : file_(std::move(file)) {}
  const std::string& file() const { return file_; }

  /// Parses a whole file; throws Error if it is missing, empty or not valid YAML.
  YAML::Node load() const;
  /// The same for YAML text embedded in the file (errors still name the file).
  YAML::Node parse(const std::string& text) const;
  /// Throws Error naming the file, the line and the key when a mapping under `node` holds a
  /// key twice (YAML forbids it; yaml-cpp keeps both, and readers took the first or the last).
  void requireUniqueKeys(const YAML::Node& node, const std::string& path = "") const;

  /// Child `key` of the mapping `node` (whose dotted name is `path`); throws if missing.
  YAML::Node child(const YAML::Node& node, const std::string& path, const std::string& key) const;
  double number(const YAML::Node& node, const std::string& path) const;
  double positive(const YAML::Node& node, const std::string& path) const;
  int positiveInt(const YAML::Node& node, const std::string& path) const;
  std::string text(const YAML::Node& node, const std::string& path) const;
  /// A sequence of exactly `size` numbers (any size when `size` is 0).
  std::vector<double> numbers(const YAML::Node& node, const std::string& path,
                              std::size_t size = 0) const;

  [[noreturn]] void fail(const YAML::Node& node, const std::string& path,
                         const std::string& expected) const;

 private:
  YAML::Node mapping(const YAML::Node& root) const;
  std::string file_;
};

}  // namespace sonarcarve

namespace sonarcarve {
/// The shortest text in degrees that reads back (through degToRad) as exactly `angle_rad`.
std::string shortestDegrees(double angle_rad);
}  // namespace sonarcarve
