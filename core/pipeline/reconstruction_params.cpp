// ReconstructionParams to and from YAML, both walking the parameter schema (param_schema.h):
// a key the schema does not know, a value of the wrong type or out of range stops the read
// with the file, the line and the key.
#include "pipeline/reconstruction_params.h"

#include <algorithm>
#include <filesystem>
#include <set>
#include <sstream>

#include "common/error.h"
#include "io/files/yaml_fields.h"
#include "pipeline/param_schema.h"

namespace sonarcarve {

namespace {

std::string joined(const std::string& prefix, const std::string& key) {
  return prefix.empty() ? key : prefix + "." + key;
}

// The keys one level below `prefix` ("" = the top), in schema order: what a mapping may hold.
std::vector<std::string> keysBelow(const std::string& prefix) {
  const std::string start = prefix.empty() ? "" : prefix + ".";
  std::vector<std::string> keys;
  for (const ParamSpec& spec : paramSchema()) {
    const std::string key(spec.key);
    if (key.compare(0, start.size(), start) != 0) {
      continue;
    }
    const std::string next = key.substr(start.size(), key.find('.', start.size()) - start.size());
    if (std::find(keys.begin(), keys.end(), next) == keys.end()) {
      keys.push_back(next);
    }
  }
  return keys;
}

std::string listed(const std::vector<std::string>& words) {
  std::string text;
  for (const std::string& w : words) {
    text += (text.empty() ? "" : ", ") + w;
  }
  return text;
}

class ParamsReader {
 public:
  // `file` names the document in errors and anchors a relative noise model path.
  ParamsReader(const YamlFields& fields, std::string file) : f_(fields), file_(std::move(file)) {}

  void readMapping(const YAML::Node& map, const std::string& prefix, ReconstructionParams& p) {
    for (auto it = map.begin(); it != map.end(); ++it) {
      const std::string key = joined(prefix, it->first.IsScalar() ? it->first.Scalar() : "?");
      const std::vector<std::string> below = keysBelow(key);
      if (const ParamSpec* spec = findParam(key)) {
        readValue(*spec, it->second, p);
      } else if (!below.empty()) {
        if (!it->second.IsMap()) {
          f_.fail(it->second, key, "expected a mapping of " + listed(below));
        }
        readMapping(it->second, key, p);
      } else if (key == "detector.arc_prior" || key == "detector.carve_log_odds") {
        // Keys of the probability detector, removed (docs/denoising.md): every parameter
        // file written before holds them; they meant nothing to the other detectors.
      } else {
        f_.fail(it->first, key, "unknown key; expected one of " + listed(keysBelow(prefix)));
      }
    }
  }

 private:
  void readValue(const ParamSpec& spec, const YAML::Node& node, ReconstructionParams& p) const {
    const std::string key(spec.key);
    if (spec.type() == ParamType::Box) {
      spec.set(p, readBox(spec, node));
      return;
    }
    if (spec.type() == ParamType::Path && node.IsNull()) {
      spec.set(p, std::string());
      return;
    }
    if (!node.IsScalar()) {
      f_.fail(node, key, "expected " + describeAccepted(spec));
    }
    ParsedValue parsed = parseParam(spec, node.Scalar());
    if (!parsed.problem.empty()) {
      f_.fail(node, key, parsed.problem);
    }
    if (spec.type() == ParamType::Path) {
      parsed.value = relativeToFile(std::get<std::string>(parsed.value));
    }
    spec.set(p, parsed.value);
  }

  // {min_m: [n, e, d], max_m: [n, e, d]}, or null for none.
  OptionalBox readBox(const ParamSpec& spec, const YAML::Node& node) const {
    const std::string key(spec.key);
    if (node.IsNull()) {
      return std::nullopt;
    }
    if (!node.IsMap()) {
      f_.fail(node, key, "expected {min_m: [N, E, D], max_m: [N, E, D]} or null");
    }
    for (auto it = node.begin(); it != node.end(); ++it) {
      const std::string name = it->first.IsScalar() ? it->first.Scalar() : "?";
      if (name != "min_m" && name != "max_m") {
        f_.fail(it->first, joined(key, name), "unknown key; expected one of min_m, max_m");
      }
    }
    const auto lo = f_.numbers(f_.child(node, key, "min_m"), key + ".min_m", 3);
    const auto hi = f_.numbers(f_.child(node, key, "max_m"), key + ".max_m", 3);
    const OptionalBox box = Eigen::AlignedBox3d(Eigen::Vector3d(lo[0], lo[1], lo[2]),
                                                Eigen::Vector3d(hi[0], hi[1], hi[2]));
    if (box->isEmpty()) {
      f_.fail(node, key, "expected min_m below max_m on every axis");
    }
    return box;
  }

  std::string relativeToFile(const std::string& path) const {
    std::filesystem::path model = path;
    if (!path.empty() && model.is_relative()) {
      model = std::filesystem::path(file_).parent_path() / model;
    }
    return model.string();
  }

  const YamlFields& f_;
  std::string file_;
};

// The node at a dotted key, for the line of an error found after reading.
YAML::Node nodeAt(YAML::Node node, const std::string& key) {
  std::istringstream parts(key);
  for (std::string part; std::getline(parts, part, '.');) {
    if (!node.IsMap() || !node[part]) {
      return YAML::Node(YAML::NodeType::Undefined);
    }
    node = node[part];
  }
  return node;
}

// A SonarCarve file of another kind says what it is in its `format` key (a mission.yaml, a
// workbench session), which no parameters file has: that is named, not the key as unknown.
void requireParametersFile(const YAML::Node& root, const YamlFields& f) {
  const YAML::Node format = root.IsMap() ? root["format"] : YAML::Node();
  if (format && format.IsScalar()) {
    f.fail(
        format, "format",
        "the file says it is a " + format.Scalar() +
            " file, not a parameters file: expected a parameters YAML (a run's params.yaml, "
            "or sonarcarve-cli params --yaml)" +
            (format.Scalar() == "sonarcarve-session" ? "; a session holds one as its params" : ""));
  }
}

ReconstructionParams paramsFromYaml(const YAML::Node& root, const YamlFields& f,
                                    const std::string& path) {
  requireParametersFile(root, f);
  ReconstructionParams p;
  ParamsReader(f, path).readMapping(root, "", p);
  try {
    p.validate();
  } catch (const Error& e) {
    // Checks across keys name a key; point at its line when the file has it.
    const YAML::Node at = nodeAt(root, e.place());
    if (at.IsDefined()) {
      f.fail(at, e.place(), e.message());
    }
    throw Error(path, e.place(), e.message());
  }
  return p;
}

// Written values: a path absolute (the file may be read from elsewhere) and quoted; a box in
// flow style; every other value as a flag takes it.
std::string yamlValue(const ParamSpec& spec, const ParamValue& value) {
  if (spec.type() == ParamType::Path) {
    const std::string& path = std::get<std::string>(value);
    return YAML::Dump(YAML::Node(path.empty() ? path : std::filesystem::absolute(path).string()));
  }
  if (spec.type() == ParamType::Box) {
    const OptionalBox& box = std::get<OptionalBox>(value);
    if (!box) {
      return "null";
    }
    const auto corner = [](const Eigen::Vector3d& v) {
      return "[" + shortestNumber(v.x()) + ", " + shortestNumber(v.y()) + ", " +
             shortestNumber(v.z()) + "]";
    };
    return "{min_m: " + corner(box->min()) + ", max_m: " + corner(box->max()) + "}";
  }
  return formatParam(spec, value);
}

void writeEntry(std::ostream& out, const std::string& indent, const std::string& key,
                const ParamSpec& spec, const ReconstructionParams& p) {
  std::string line = indent + key + ": " + yamlValue(spec, spec.get(p));
  line.resize(std::max<std::size_t>(line.size() + 2, 36), ' ');
  const std::string unit = spec.unit.empty() ? "" : std::string(spec.unit) + "; ";
  const std::string accepted = spec.type() == ParamType::Box
                                   ? "null or {min_m: [N, E, D], max_m: [N, E, D]}"
                                   : describeAccepted(spec);
  out << line << "# " << unit << accepted << "\n";
}

}  // namespace

ReconstructionParams ReconstructionParams::fromYamlFile(const std::string& path) {
  const YamlFields f(path);
  return paramsFromYaml(f.load(), f, path);
}

ReconstructionParams ReconstructionParams::fromYamlText(const std::string& text,
                                                        const std::string& source) {
  const YamlFields f(source);
  return paramsFromYaml(f.parse(text), f, source);
}

ReconstructionParams ReconstructionParams::fromYamlNode(const YAML::Node& node,
                                                        const std::string& source) {
  const YamlFields f(source);
  if (!node.IsMap()) {
    f.fail(node, "params", "expected a mapping of parameters");
  }
  return paramsFromYaml(node, f, source);
}

void ReconstructionParams::validate() const {
  for (const ParamSpec& spec : paramSchema()) {
    const std::string problem = checkParam(spec, spec.get(*this));
    if (!problem.empty()) {
      throw Error("parameters", std::string(spec.key), problem);
    }
  }
  if (carve.range_max_m > 0.0 && carve.range_max_m <= carve.range_min_m) {
    throw Error("parameters", "range_max_m", "expected 0 (the sonar's) or above range_min_m");
  }
  detector.validate();
  mesh.validate();
  if (detector.needsNoiseModel() && noise_model.empty()) {
    throw Error("parameters", "detector.mode",
                "the " + std::string(toString(detector.mode)) +
                    " detector needs a noise model file (noise_model)");
  }
}

std::string ReconstructionParams::toYaml() const {
  std::ostringstream out;
  out << "# SonarCarve reconstruction parameters (sonarcarve-cli params --markdown explains "
         "each key)\n";
  std::set<std::string> groups_written;
  for (const ParamSpec& spec : paramSchema()) {
    const std::string key(spec.key);
    const std::size_t dot = key.find('.');
    if (dot == std::string::npos) {
      writeEntry(out, "", key, spec, *this);
      continue;
    }
    const std::string group = key.substr(0, dot);
    if (!groups_written.insert(group).second) {
      continue;
    }
    out << group << ":\n";
    for (const ParamSpec& member : paramSchema()) {
      const std::string member_key(member.key);
      if (member_key.compare(0, dot + 1, group + ".") == 0) {
        writeEntry(out, "  ", member_key.substr(dot + 1), member, *this);
      }
    }
  }
  return out.str();
}

}  // namespace sonarcarve
