#include "io/mission/sonar_yaml.h"

#include <optional>

#include "common/angles.h"
#include "common/error.h"
#include "sonar/mission_origin.h"
#include "sonar/sonar_ranges.h"

namespace sonarcarve {
namespace {

// A number within its physically meaningful range; an error names the file, the line, the
// key and the range.
double physical(const YamlFields& fields, const YAML::Node& node, const std::string& path,
                const PhysicalRange& range) {
  const double value = fields.number(node, path);
  if (const auto problem = outsideRange(value, range)) {
    fields.fail(node, path, *problem);
  }
  return value;
}

double physicalChild(const YamlFields& fields, const YAML::Node& node, const std::string& path,
                     const std::string& key, const PhysicalRange& range) {
  return physical(fields, fields.child(node, path, key), path + "." + key, range);
}

BearingTable bearingsFromYaml(const YAML::Node& node, const YamlFields& fields,
                              const std::string& path) {
  if (!node.IsMap()) {
    fields.fail(node, path, "expected a mapping with fov_deg and beams, or table_deg");
  }
  try {
    if (node["table_deg"]) {
      std::vector<double> centres = fields.numbers(node["table_deg"], path + ".table_deg");
      for (std::size_t j = 0; j < centres.size(); ++j) {
        if (const auto problem = outsideRange(centres[j], kBearing)) {
          fields.fail(node["table_deg"], path + ".table_deg[" + std::to_string(j) + "]", *problem);
        }
        centres[j] = degToRad(centres[j]);
      }
      return BearingTable::fromCentres(std::move(centres));
    }
    const double fov = physicalChild(fields, node, path, "fov_deg", kFieldOfView);
    const int beams = fields.positiveInt(fields.child(node, path, "beams"), path + ".beams");
    return BearingTable::uniform(degToRad(fov), beams);
  } catch (const Error& e) {
    if (e.source() == "sonar model") {
      fields.fail(node, path, e.place() + ": " + e.message());
    }
    throw;
  }
}

// `intensity:` absent or `linear`, or {scale: decibel, full_scale_db: 80, full_scale_count: 255}.
IntensityScale intensityFromYaml(const YAML::Node& node, const YamlFields& fields,
                                 const std::string& path) {
  if (!node) {
    return IntensityScale::linear();
  }
  const char* expected =
      "expected 'linear' or a mapping {scale: decibel, full_scale_db, full_scale_count} or "
      "{scale: gamma, gamma, full_scale_count}";
  if (node.IsScalar()) {
    if (fields.text(node, path) != "linear") {
      fields.fail(node, path, expected);
    }
    return IntensityScale::linear();
  }
  if (!node.IsMap()) {
    fields.fail(node, path, expected);
  }
  const YAML::Node scale = fields.child(node, path, "scale");
  const std::string name = fields.text(scale, path + ".scale");
  if (name == "linear") {
    return IntensityScale::linear();
  }
  if (name == "gamma") {
    const YAML::Node gamma = fields.child(node, path, "gamma");
    const double exponent = physical(fields, gamma, path + ".gamma", kGammaExponent);
    const double full_scale =
        physicalChild(fields, node, path, "full_scale_count", kFullScaleCount);
    try {
      return IntensityScale::gamma(exponent, full_scale);
    } catch (const Error& e) {
      fields.fail(gamma, path + "." + e.place(), e.message());
    }
  }
  if (name != "decibel") {
    fields.fail(scale, path + ".scale", "expected 'linear', 'decibel' or 'gamma'");
  }
  return IntensityScale::decibel(
      physicalChild(fields, node, path, "full_scale_db", kFullScaleDb),
      physicalChild(fields, node, path, "full_scale_count", kFullScaleCount));
}

void emitIntensity(YAML::Emitter& out, const IntensityScale& scale) {
  out << YAML::Flow << YAML::BeginMap;
  if (!scale.isDecibel()) {
    out << YAML::Key << "scale" << YAML::Value << "gamma";
    out << YAML::Key << "gamma" << YAML::Value << shortestNumber(scale.gammaExponent());
    out << YAML::Key << "full_scale_count" << YAML::Value << shortestNumber(scale.fullScaleCount());
    out << YAML::EndMap;
    return;
  }
  out << YAML::Key << "scale" << YAML::Value << "decibel";
  out << YAML::Key << "full_scale_db" << YAML::Value << shortestNumber(scale.fullScaleDb());
  out << YAML::Key << "full_scale_count" << YAML::Value << shortestNumber(scale.fullScaleCount());
  out << YAML::EndMap;
}

}  // namespace

SonarModel sonarFromYaml(const YAML::Node& node, const YamlFields& fields,
                         const std::string& path) {
  const std::string id = fields.text(fields.child(node, path, "id"), path + ".id");
  const YAML::Node range_node = fields.child(node, path, "range");
  const std::string rp = path + ".range";
  RangeBins range;
  range.min_m = physicalChild(fields, range_node, rp, "min_m", kNearRange);
  range.resolution_m = physicalChild(fields, range_node, rp, "resolution_m", kRangeResolution);
  range.count = fields.positiveInt(fields.child(range_node, rp, "bins"), rp + ".bins");
  BearingTable bearings =
      bearingsFromYaml(fields.child(node, path, "bearings"), fields, path + ".bearings");
  const YAML::Node aperture_node = fields.child(node, path, "vertical_aperture_deg");
  const double aperture_deg =
      physical(fields, aperture_node, path + ".vertical_aperture_deg", kVerticalAperture);
  ElevationBeam beam = ElevationBeam::MainLobe;
  if (node["beam_pattern"]) {
    const std::string pattern = fields.text(node["beam_pattern"], path + ".beam_pattern");
    if (pattern == "clipped") {
      beam = ElevationBeam::Clipped;
    } else if (pattern != "sinc") {
      fields.fail(node["beam_pattern"], path + ".beam_pattern",
                  "expected 'sinc' (a real beam) or 'clipped' (nothing imaged outside the "
                  "aperture)");
    }
  }
  const IntensityScale intensity =
      intensityFromYaml(node["intensity"], fields, path + ".intensity");
  double beam_width_deg = 0.0;
  if (const YAML::Node width = node["horizontal_beam_width_deg"]) {
    beam_width_deg =
        physical(fields, width, path + ".horizontal_beam_width_deg", kHorizontalBeamWidth);
    if (degToRad(beam_width_deg) >= bearings.fieldOfView()) {
      fields.fail(width, path + ".horizontal_beam_width_deg",
                  "expected less than the field of view");
    }
  }
  std::optional<SonarModel> sonar;
  try {
    sonar = SonarModel(id, range, std::move(bearings), degToRad(aperture_deg))
                .withElevationBeam(beam)
                .withHorizontalBeamWidth(degToRad(beam_width_deg))
                .withIntensityScale(intensity);
  } catch (const Error& e) {
    fields.fail(node, path, e.place() + ": " + e.message());
  }
  // After the model's own checks, which bound the bins.
  if (range.maxRange() > kMaxFarRange_m) {
    fields.fail(range_node, rp,
                "reaches " + shortestNumber(range.maxRange()) +
                    " m (min_m + bins x resolution_m): expected at most " +
                    shortestNumber(kMaxFarRange_m) + " m");
  }

  return *sonar;
}

void emitSonar(YAML::Emitter& out, const SonarModel& sonar) {
  out << YAML::BeginMap;
  out << YAML::Key << "id" << YAML::Value << sonar.id();
  out << YAML::Key << "range" << YAML::Value << YAML::Flow << YAML::BeginMap;
  out << YAML::Key << "min_m" << YAML::Value << shortestNumber(sonar.range().min_m);
  out << YAML::Key << "resolution_m" << YAML::Value << shortestNumber(sonar.range().resolution_m);
  out << YAML::Key << "bins" << YAML::Value << sonar.range().count;
  out << YAML::EndMap;
  const BearingTable& b = sonar.bearings();
  out << YAML::Key << "bearings" << YAML::Value;
  if (b.isUniform()) {
    out << YAML::Flow << YAML::BeginMap;
    out << YAML::Key << "fov_deg" << YAML::Value << shortestDegrees(b.fieldOfView());
    out << YAML::Key << "beams" << YAML::Value << b.count();
    out << YAML::EndMap;
  } else {
    out << YAML::BeginMap << YAML::Key << "table_deg" << YAML::Value << YAML::Flow
        << YAML::BeginSeq;
    for (double c : b.centres()) {
      out << shortestDegrees(c);
    }
    out << YAML::EndSeq << YAML::EndMap;
  }
  out << YAML::Key << "vertical_aperture_deg" << YAML::Value
      << shortestDegrees(sonar.verticalAperture());
  out << YAML::Key << "beam_pattern" << YAML::Value << elevationBeamName(sonar.elevationBeam());
  if (sonar.horizontalBeamWidth() > 0.0) {  // not given: left out
    out << YAML::Key << "horizontal_beam_width_deg" << YAML::Value
        << shortestDegrees(sonar.horizontalBeamWidth());
  }
  if (!sonar.intensityScale().isLinear()) {  // linear, the default, is left implicit
    out << YAML::Key << "intensity" << YAML::Value;
    emitIntensity(out, sonar.intensityScale());
  }
  out << YAML::EndMap;
}

Mounting mountingFromYaml(const YAML::Node& node, const YamlFields& fields,
                          const std::string& path) {
  Mounting m;
  const auto t =
      fields.numbers(fields.child(node, path, "translation_m"), path + ".translation_m", 3);
  m.translation_m = Eigen::Vector3d(t[0], t[1], t[2]);
  if (const auto problem = mountingOffsetProblem(m.translation_m)) {
    fields.fail(node["translation_m"], path + ".translation_m", *problem);
  }
  const auto r = fields.numbers(fields.child(node, path, "roll_pitch_yaw_deg"),
                                path + ".roll_pitch_yaw_deg", 3);
  for (std::size_t k = 0; k < r.size(); ++k) {
    if (const auto problem = outsideRange(r[k], kMountingAngle)) {
      fields.fail(node["roll_pitch_yaw_deg"],
                  path + ".roll_pitch_yaw_deg[" + std::to_string(k) + "]", *problem);
    }
  }
  m.rpy = RollPitchYaw{degToRad(r[0]), degToRad(r[1]), degToRad(r[2])};
  return m;
}

void emitMounting(YAML::Emitter& out, const Mounting& m) {
  out << YAML::BeginMap;
  out << YAML::Key << "translation_m" << YAML::Value << YAML::Flow << YAML::BeginSeq
      << shortestNumber(m.translation_m.x()) << shortestNumber(m.translation_m.y())
      << shortestNumber(m.translation_m.z()) << YAML::EndSeq;
  out << YAML::Key << "roll_pitch_yaw_deg" << YAML::Value << YAML::Flow << YAML::BeginSeq
      << shortestDegrees(m.rpy.roll_rad) << shortestDegrees(m.rpy.pitch_rad)
      << shortestDegrees(m.rpy.yaw_rad) << YAML::EndSeq;
  out << YAML::EndMap;
}

}  // namespace sonarcarve
