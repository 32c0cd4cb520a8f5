// JSON written by SonarCarve (report.json, manifest.json, `info --json`) is always valid UTF-8.
// Paths are bytes: a mission or --out path that is not UTF-8 (a Latin-1 name from an old disk)
// made nlohmann::json throw when the report was written, and the finished run's results were
// lost. Such bytes are written as U+FFFD (the replacement character) instead: the JSON names
// the path as closely as UTF-8 allows, the files themselves keep their real names.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <string>

namespace sonarcarve {

/// `value` as JSON text, indented by `indent` spaces (-1: on one line); each byte of a string
/// that is not part of valid UTF-8 becomes U+FFFD.
std::string jsonText(const nlohmann::json& value, int indent = 2);

}  // namespace sonarcarve
