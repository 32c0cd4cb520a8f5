// The parameter schema and the YAML it drives: every entry survives a round trip, and every
// kind of bad file is refused with the file, the line and the key.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <set>

#include "common/angles.h"
#include "pipeline/param_schema.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

// A valid value other than the default, in struct units, for any entry: the schema decides,
// so that an entry added later is covered without touching this test.
ParamValue otherValue(const ParamSpec& spec, const std::filesystem::path& dir) {
  const ParamValue value = spec.defaultValue();
  switch (spec.type()) {
    case ParamType::Number: {
      const double shown = spec.toShown(std::get<double>(value));
      const double up = shown + 0.01;
      const double down = shown - 0.01;
      // A default of 0 beside a range that starts higher ("0 = the sonar's own"): its start.
      return spec.fromShown(spec.range.contains(up)     ? up
                            : spec.range.contains(down) ? down
                                                        : spec.range.min);
    }
    case ParamType::Integer: {
      const long long v = std::get<long long>(value);
      return spec.range.contains(static_cast<double>(v + 2)) ? v + 2 : v - 2;
    }
    case ParamType::Bool:
      return !std::get<bool>(value);
    case ParamType::Enum: {
      // The next name; its own needs are met by the defaults (none needs no noise model).
      const auto& choices = spec.access.choices;
      const auto at = std::find(choices.begin(), choices.end(), std::get<std::string>(value));
      return std::string(*(at + 1 == choices.end() ? choices.begin() : at + 1));
    }
    case ParamType::Path:
      return (dir / "noise.yaml").string();
    case ParamType::Box:
      return OptionalBox(
          Eigen::AlignedBox3d(Eigen::Vector3d(-1, -2.5, 3), Eigen::Vector3d(4, 5, 6.25)));
  }
  return value;
}

void expectSameParams(const ReconstructionParams& a, const ReconstructionParams& b,
                      const std::string& context) {
  for (const ParamSpec& spec : paramSchema()) {
    EXPECT_EQ(formatParam(spec, spec.get(a)), formatParam(spec, spec.get(b)))
        << spec.key << " (" << context << ")";
  }
  EXPECT_EQ(a.toYaml(), b.toYaml()) << context;
}

TEST(ParamSchema, EveryEntryRoundTripsThroughYaml) {
  test::ScratchDir dir;
  const auto file = dir.path() / "p.yaml";
  for (const ParamSpec& spec : paramSchema()) {
    ReconstructionParams p;
    const ParamValue value = otherValue(spec, dir.path());
    ASSERT_EQ(checkParam(spec, value), "") << spec.key;
    ASSERT_NE(formatParam(spec, value), formatParam(spec, spec.defaultValue())) << spec.key;
    spec.set(p, value);
    test::writeText(file, p.toYaml());
    const ReconstructionParams back = ReconstructionParams::fromYamlFile(file.string());
    expectSameParams(back, p, std::string(spec.key));
  }
}

TEST(ParamSchema, DefaultsFileReadsBackAsTheDefaults) {
  const ReconstructionParams defaults;
  expectSameParams(ReconstructionParams::fromYamlText(defaults.toYaml(), "defaults.yaml"), defaults,
                   "defaults");
  // Every entry is written, the two occupancy keys too.
  for (const ParamSpec& spec : paramSchema()) {
    const std::string key(spec.key);
    const std::string leaf = key.substr(key.find('.') + 1);
    EXPECT_NE(defaults.toYaml().find(leaf + ": "), std::string::npos) << key;
  }
}

TEST(ParamSchema, EntriesAreWellFormed) {
  std::set<std::string_view> keys;
  std::set<std::string_view> flags;
  for (const ParamSpec& spec : paramSchema()) {
    EXPECT_TRUE(keys.insert(spec.key).second) << "twice: " << spec.key;
    EXPECT_TRUE(flags.insert(spec.flag).second) << "twice: " << spec.flag;
    EXPECT_EQ(spec.flag.substr(0, 2), "--") << spec.key;
    EXPECT_FALSE(spec.help.empty()) << spec.key;
    EXPECT_FALSE(spec.gui.group.empty()) << spec.key;
    EXPECT_FALSE(spec.gui.label.empty()) << spec.key;
    // The writer nests one level only.
    EXPECT_LE(std::count(spec.key.begin(), spec.key.end(), '.'), 1) << spec.key;
    EXPECT_EQ(checkParam(spec, spec.defaultValue()), "") << spec.key;
    EXPECT_EQ(findParam(spec.key), &spec);
  }
  // The flags the user guide and scripts have always used.
  for (const char* flag :
       {"--engine", "--voxel-size", "--threshold", "--elevation-step", "--stride", "--noise-model",
        "--detector", "--z", "--cfar-pfa", "--smoothing", "--min-views", "--region"}) {
    EXPECT_EQ(flags.count(flag), 1u) << flag;
  }
}

TEST(ParamSchema, DegreesAreConvertedAtTheBoundaryOnly) {
  const ParamSpec& step = *findParam("elevation_step_deg");
  const ParsedValue parsed = parseParam(step, "0.5");
  ASSERT_EQ(parsed.problem, "");
  EXPECT_DOUBLE_EQ(std::get<double>(parsed.value), degToRad(0.5));
  EXPECT_EQ(formatParam(step, step.defaultValue()), "0.2");
}

class ParamsYamlErrors : public ::testing::Test {
 protected:
  // The error text for `yaml`, read from a file named p.yaml.
  std::string errorOf(const std::string& yaml) {
    test::writeText(file_, yaml);
    try {
      ReconstructionParams::fromYamlFile(file_.string());
    } catch (const Error& e) {
      return e.what();
    }
    ADD_FAILURE() << "accepted: " << yaml;
    return "";
  }
  std::string at(int line, const std::string& key) const {
    return file_.string() + ": line " + std::to_string(line) + ": " + key + ": ";
  }

  test::ScratchDir dir_;
  std::filesystem::path file_ = dir_.path() / "p.yaml";
};

TEST_F(ParamsYamlErrors, AWordWhereANumberBelongs) {
  EXPECT_EQ(errorOf("engine: fast\ndetector:\n  mode: ztest\n  z: high\n"),
            at(4, "detector.z") + "expected a number, got 'high'");
}

TEST_F(ParamsYamlErrors, ANumberWhereAnEnumBelongs) {
  EXPECT_EQ(errorOf("voxel_size_m: 0.02\nengine: 3\n"),
            at(2, "engine") + "expected fast or reference, got '3'");
  EXPECT_EQ(errorOf("mesh: {method: 1}\n"),
            at(1, "mesh.method") + "expected occupancy or implicit, got '1'");
}

TEST_F(ParamsYamlErrors, UnknownKeysAtAnyLevel) {
  EXPECT_EQ(errorOf("frames:\n  first: 2\n  strid: 3\n")
                .rfind(at(3, "frames.strid") + "unknown key; expected one of "
                                               "first, last, stride",
                       0),
            0u);
  EXPECT_EQ(errorOf("voxel_size: 0.02\n").rfind(at(1, "voxel_size") + "unknown key", 0), 0u);
  EXPECT_EQ(errorOf("region: {min_m: [0, 0, 0], max_m: [1, 1, 1], mid_m: 0}\n")
                .rfind(at(1, "region.mid_m") + "unknown key", 0),
            0u);
}

TEST_F(ParamsYamlErrors, OutOfRangeValues) {
  EXPECT_EQ(errorOf("mesh:\n  decimate: 0.99\n"),
            at(2, "mesh.decimate") + "expected a number, from 0 to 0.95, got 0.99");
  EXPECT_EQ(errorOf("frames: {stride: 0}\n"),
            at(1, "frames.stride") + "expected a whole number, at least 1, got 0");
  EXPECT_EQ(errorOf("detector: {smoothing: 4}\n"),
            at(1, "detector.smoothing") + "expected an odd whole number, from 1 to 255, got 4");
  // Parameters that set a run's work have an upper end (issue 44).
  EXPECT_EQ(errorOf("mesh: {smoothing_iterations: 100000000}\n"),
            at(1, "mesh.smoothing_iterations") +
                "expected a whole number, from 0 to 1000, got 100000000");
  EXPECT_EQ(errorOf("mesh: {occupancy_sigma_voxels: 1e6}\n"),
            at(1, "mesh.occupancy_sigma_voxels") +
                "expected a number, above 0 and at most 100, got 1e+06");
  EXPECT_EQ(errorOf("vertical_aperture_deg: 200\n"),
            at(1, "vertical_aperture_deg") +
                "expected a number, 0 or at least 0.1 and below 180, got 200");
}

TEST_F(ParamsYamlErrors, WrongTypesOfEveryKind) {
  EXPECT_EQ(errorOf("mesh: {enabled: maybe}\n"),
            at(1, "mesh.enabled") + "expected true or false, got 'maybe'");
  EXPECT_EQ(errorOf("frames: {stride: 1.5}\n"),
            at(1, "frames.stride") + "expected a whole number, at least 1, got '1.5'");
  EXPECT_EQ(errorOf("detector: 3\n"), at(1, "detector") +
                                          "expected a mapping of mode, z, cfar_pfa, smoothing, "
                                          "cfar_guard, cfar_train");
  // The probability detector was removed (docs/denoising.md): a file asking for it is refused.
  EXPECT_EQ(errorOf("detector: {mode: probability}\n"),
            at(1, "detector.mode") + "expected auto, none, ztest or cfar, got 'probability'");
  EXPECT_EQ(errorOf("voxel_size_m: [1, 2]\n"),
            at(1, "voxel_size_m") + "expected a number, above 0 and at most 10");
}

TEST_F(ParamsYamlErrors, ChecksAcrossKeysPointAtALine) {
  EXPECT_EQ(errorOf("range_min_m: 5\nrange_max_m: 4\n"),
            at(2, "range_max_m") + "expected 0 (the sonar's) or above range_min_m");
  EXPECT_EQ(errorOf("detector:\n  mode: ztest\n"),
            at(2, "detector.mode") + "the ztest detector needs a noise model file (noise_model)");
}

TEST(ParamsYaml, ANodeOfALargerFileGivesThatFilesLines) {
  // A GUI session embeds the parameters under `params:`.
  const YAML::Node session = YAML::Load("format: session\nparams:\n  detector:\n    z: high\n");
  test::expectError([&] { ReconstructionParams::fromYamlNode(session["params"], "s.sonarcarve"); },
                    {"s.sonarcarve: line 4: detector.z: expected a number, got 'high'"});
}

TEST(ParamsYaml, ReadsTheFlowStyleOfEarlierVersions) {
  const ReconstructionParams p = ReconstructionParams::fromYamlText(
      "engine: reference\nvoxel_size_m: 0.03\nframes: {first: 0, last: -1, stride: 2}\n"
      "detector: {mode: cfar, z: 2, cfar_guard: 3, cfar_train: 12, cfar_pfa: 0.05, "
      "arc_prior: 2, carve_log_odds: -4, smoothing: 3}\n"
      "mesh: {enabled: false, method: implicit, smoothing_iterations: 15, decimate: 0, "
      "min_fragment_triangles: 200}\n",
      "old.yaml");
  EXPECT_EQ(p.engine, Engine::Reference);
  EXPECT_EQ(p.detector.mode, DetectorMode::Cfar);
  EXPECT_EQ(p.mesh.method, MeshMethod::Implicit);
  EXPECT_FALSE(p.mesh_enabled);
  EXPECT_EQ(p.stride, 2u);
}

}  // namespace
}  // namespace sonarcarve
