// Parsing, checking and writing single parameter values (param_schema.h). Numbers are read with
// std::from_chars, not strtod: the workbench runs under the user's locale, where strtod would
// read "0,5" and refuse "0.5".
#include <algorithm>
#include <cctype>
#include <charconv>
#include <climits>
#include <cmath>
#include <sstream>

#include "io/files/yaml_fields.h"
#include "pipeline/param_schema.h"

namespace sonarcarve {
namespace {

std::optional<double> parseNumber(std::string_view text) {
  if (!text.empty() && text.front() == '+') {
    text.remove_prefix(1);
  }
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() ||
      !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

std::optional<long long> parseInteger(std::string_view text) {
  if (!text.empty() && text.front() == '+') {
    text.remove_prefix(1);
  }
  long long value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size()) {
    return std::nullopt;
  }
  return value;
}

// YAML 1.1's words for booleans, which yaml-cpp also accepts.
std::optional<bool> parseBool(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (text == "true" || text == "yes" || text == "on") {
    return true;
  }
  if (text == "false" || text == "no" || text == "off") {
    return false;
  }
  return std::nullopt;
}

// Six numbers separated by spaces or commas: N0 E0 D0 N1 E1 D1.
std::optional<Eigen::AlignedBox3d> parseBox(std::string text) {
  std::replace(text.begin(), text.end(), ',', ' ');
  std::istringstream in(text);
  std::vector<double> values;
  for (std::string word; in >> word;) {
    const auto value = parseNumber(word);
    if (!value) {
      return std::nullopt;
    }
    values.push_back(*value);
  }
  if (values.size() != 6) {
    return std::nullopt;
  }
  return Eigen::AlignedBox3d(Eigen::Vector3d(values[0], values[1], values[2]),
                             Eigen::Vector3d(values[3], values[4], values[5]));
}

// The text as the entry's type, in struct units; nothing if it is not of that type.
std::optional<ParamValue> typedValue(const ParamSpec& spec, const std::string& text) {
  switch (spec.type()) {
    case ParamType::Number:
      if (const auto shown = parseNumber(text)) {
        return ParamValue(spec.fromShown(*shown));
      }
      return std::nullopt;
    case ParamType::Integer:
      if (const auto value = parseInteger(text)) {
        return ParamValue(*value);
      }
      return std::nullopt;
    case ParamType::Bool:
      if (const auto value = parseBool(text)) {
        return ParamValue(*value);
      }
      return std::nullopt;
    case ParamType::Enum:
    case ParamType::Path:
      return ParamValue(text);
    case ParamType::Box:
      if (const auto box = parseBox(text)) {
        return ParamValue(OptionalBox(*box));
      }
      return std::nullopt;
  }
  return std::nullopt;
}

std::string joinChoices(const std::vector<std::string_view>& choices) {
  std::string text;
  for (std::size_t i = 0; i < choices.size(); ++i) {
    if (i > 0) {
      text += i + 1 == choices.size() ? " or " : ", ";
    }
    text += choices[i];
  }
  return text;
}

std::string withRange(std::string what, const ParamRange& range) {
  const std::string bounds = range.describe();
  return bounds.empty() ? what : what + ", " + bounds;
}

std::string expected(const ParamSpec& spec, const std::string& got) {
  return "expected " + describeAccepted(spec) + ", got " + got;
}

}  // namespace

bool ParamRange::contains(double shown) const {
  const bool above_min = min_open ? shown > min : shown >= min;
  const bool below_max = max_open ? shown < max : shown <= max;
  return (above_min && below_max) || (or_zero && shown == 0.0);
}

std::string ParamRange::describe() const {
  const bool has_min = std::isfinite(min);
  const bool has_max = std::isfinite(max);
  const std::string lower = (min_open ? "above " : "at least ") + shortestNumber(min);
  const std::string upper = (max_open ? "below " : "at most ") + shortestNumber(max);
  std::string bounds;
  if (has_min && has_max) {
    bounds = !min_open && !max_open ? "from " + shortestNumber(min) + " to " + shortestNumber(max)
                                    : lower + " and " + upper;
  } else {
    bounds = has_min ? lower : has_max ? upper : "";
  }
  return or_zero && !bounds.empty() ? "0 or " + bounds : bounds;
}

std::string describeAccepted(const ParamSpec& spec) {
  switch (spec.type()) {
    case ParamType::Number:
      return withRange("a number", spec.range);
    case ParamType::Integer:
      return withRange(spec.odd ? "an odd whole number" : "a whole number", spec.range);
    case ParamType::Bool:
      return "true or false";
    case ParamType::Enum:
      return joinChoices(spec.access.choices);
    case ParamType::Path:
      return "a file path (\"\" = none)";
    case ParamType::Box:
      return "six numbers N0 E0 D0 N1 E1 D1, min below max on every axis";
  }
  return "";
}

std::string checkParam(const ParamSpec& spec, const ParamValue& value) {
  switch (spec.type()) {
    case ParamType::Number: {
      const double shown = spec.toShown(std::get<double>(value));
      return std::isfinite(shown) && spec.range.contains(shown)
                 ? ""
                 : expected(spec, formatParam(spec, value));
    }
    case ParamType::Integer: {
      const long long v = std::get<long long>(value);
      // The struct's fields are at least 32 bits wide.
      const bool fits = v >= INT_MIN && v <= INT_MAX;
      const bool odd_ok = !spec.odd || v % 2 != 0;
      return fits && odd_ok && spec.range.contains(static_cast<double>(v))
                 ? ""
                 : expected(spec, std::to_string(v));
    }
    case ParamType::Enum: {
      const auto& choices = spec.access.choices;
      const std::string& name = std::get<std::string>(value);
      return std::find(choices.begin(), choices.end(), name) != choices.end()
                 ? ""
                 : expected(spec, "'" + name + "'");
    }
    case ParamType::Box: {
      const OptionalBox& box = std::get<OptionalBox>(value);
      return !box || !box->isEmpty() ? "" : expected(spec, formatParam(spec, value));
    }
    case ParamType::Bool:
    case ParamType::Path:
      return "";
  }
  return "";
}

ParsedValue parseParam(const ParamSpec& spec, const std::string& text) {
  const std::optional<ParamValue> value = typedValue(spec, text);
  if (!value) {
    return {{}, expected(spec, "'" + text + "'")};
  }
  return {*value, checkParam(spec, *value)};
}

std::string formatParam(const ParamSpec& spec, const ParamValue& value) {
  switch (spec.type()) {
    case ParamType::Number: {
      const double v = std::get<double>(value);
      return spec.degrees ? shortestDegrees(v) : shortestNumber(v);
    }
    case ParamType::Integer:
      return std::to_string(std::get<long long>(value));
    case ParamType::Bool:
      return std::get<bool>(value) ? "true" : "false";
    case ParamType::Enum:
    case ParamType::Path:
      return std::get<std::string>(value);
    case ParamType::Box: {
      const OptionalBox& box = std::get<OptionalBox>(value);
      if (!box) {
        return "";
      }
      std::string text;
      for (const Eigen::Vector3d& corner : {box->min(), box->max()}) {
        for (int axis = 0; axis < 3; ++axis) {
          text += (text.empty() ? "" : " ") + shortestNumber(corner[axis]);
        }
      }
      return text;
    }
  }
  return "";
}

}  // namespace sonarcarve
