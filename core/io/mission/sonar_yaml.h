// The sonar model and mounting as YAML (the `sonar:` and `mounting:` sections of a mission,
// also used by noise models and settings). Degrees in the file, radians inside.
#pragma once

#include <yaml-cpp/yaml.h>

#include "io/files/yaml_fields.h"
#include "sonar/mounting.h"
#include "sonar/sonar_model.h"

namespace sonarcarve {

/// Reads a `sonar:` mapping; `path` is its dotted name for error messages.
SonarModel sonarFromYaml(const YAML::Node& node, const YamlFields& fields,
                         const std::string& path = "sonar");
void emitSonar(YAML::Emitter& out, const SonarModel& sonar);

Mounting mountingFromYaml(const YAML::Node& node, const YamlFields& fields,
                          const std::string& path = "mounting");
void emitMounting(YAML::Emitter& out, const Mounting& mounting);

}  // namespace sonarcarve
