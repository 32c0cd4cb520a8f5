// The one table of reconstruction parameters. Each entry names a field of ReconstructionParams
// once: its YAML key, type, unit as users see it, valid range, one-line help, CLI flag and
// place in the GUI panel. The YAML reader and writer, the CLI flags of `reconstruct`, the
// workbench's panel and the docs table are all derived from it, so they cannot drift apart.
// Defaults are not repeated here: they are whatever a default-constructed struct holds.
// Values travel in the struct's own units (SI, radians); `degrees` entries are shown, read
// and written in degrees, and the conversion happens here and nowhere else.
#pragma once

#include <Eigen/Geometry>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "pipeline/reconstruction_params.h"

namespace sonarcarve {

enum class ParamType { Number, Integer, Bool, Enum, Path, Box };

using OptionalBox = std::optional<Eigen::AlignedBox3d>;
/// Number: double; Integer: long long; Bool: bool; Enum: its name; Path: std::string
/// ("" = none); Box: OptionalBox.
using ParamValue = std::variant<double, long long, bool, std::string, OptionalBox>;

/// Valid values of a Number or Integer, in shown units. Open ends are excluded.
struct ParamRange {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;
  bool max_open = false;
  bool or_zero = false;  ///< 0 is valid too, outside the range: "0 = the sonar's own"
  bool contains(double shown) const;
  /// "above 0", "at least 1", "from 0 to 0.95", "0 or from 0.1 to 90", "" when unbounded.
  std::string describe() const;
};

/// Where and how the workbench's panel shows an entry; editor bounds are the usual values
/// (a subset of the valid range), in shown units times `factor`.
struct ParamGui {
  std::string_view group;
  std::string_view label;
  bool advanced = false;  ///< only under "More parameters", to keep the panel short
  double min = 0.0;
  double max = 0.0;
  double step = 1.0;
  int decimals = 2;
  double factor = 1.0;        ///< the panel shows value x factor (voxel size in cm)
  std::string_view suffix;    ///< " cm", "°"
  std::string_view min_text;  ///< shown instead of the minimum ("sonar's own", "end")
};

/// Reads and writes one field of ReconstructionParams as a ParamValue.
struct ParamAccess {
  ParamType type = ParamType::Number;
  std::vector<std::string_view> choices;  ///< Enum names
  std::function<ParamValue(const ReconstructionParams&)> get;
  std::function<void(ReconstructionParams&, const ParamValue&)> set;
};

struct ParamSpec {
  std::string_view key;   ///< YAML path: "detector.z"
  std::string_view unit;  ///< as shown to users: "m", "degrees", "views", "" for none
  bool degrees = false;   ///< the struct holds radians; files, flags and the panel degrees
  bool odd = false;       ///< Integer: odd values only
  ParamRange range;
  std::string_view help;  ///< one line
  std::string_view flag;  ///< "--voxel-size"
  ParamGui gui;
  ParamAccess access;
  /// Whether the entry matters for these params (null: always); the panel greys it out.
  bool (*applies)(const ReconstructionParams&) = nullptr;

  ParamType type() const { return access.type; }
  ParamValue get(const ReconstructionParams& p) const { return access.get(p); }
  void set(ReconstructionParams& p, const ParamValue& v) const { access.set(p, v); }
  ParamValue defaultValue() const { return get(ReconstructionParams{}); }
  /// Struct units to shown units (radians to degrees) and back.
  double toShown(double value) const;
  double fromShown(double shown) const;
};

/// Every parameter, in the order of the panel and the docs.
const std::vector<ParamSpec>& paramSchema();
/// The entry with this YAML key, or null.
const ParamSpec* findParam(std::string_view key);

/// A value parsed from text, or what was expected instead.
struct ParsedValue {
  ParamValue value;
  std::string problem;  ///< "" when valid
};

/// Parses `text` as typed in a file, a flag or the panel (shown units; a Box as six numbers
/// "N0 E0 D0 N1 E1 D1") and checks it.
ParsedValue parseParam(const ParamSpec& spec, const std::string& text);
/// "" when `value` (struct units) is valid for `spec`, else what was expected, e.g.
/// "expected a number above 0, got -1".
std::string checkParam(const ParamSpec& spec, const ParamValue& value);
/// The value as a file or a flag takes it: shortest exact numbers, degrees where shown so.
/// A Box as "N0 E0 D0 N1 E1 D1", "" when unset.
std::string formatParam(const ParamSpec& spec, const ParamValue& value);
/// What the entry accepts, for help texts and docs: "a number above 0", "fast or reference".
std::string describeAccepted(const ParamSpec& spec);

}  // namespace sonarcarve
