// End to end, as a user runs it: simulate the noise-free riser demo, reconstruct it at the
// default parameters (2 cm voxels), evaluate against the ground truth, open the map with
// OctoMap's own tools.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>

#include "support/cli_runner.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

using test::quoted;
using test::runCli;

std::string commandOutput(const std::string& command) {
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  std::string text;
  if (pipe == nullptr) {
    return text;
  }
  char buffer[512];
  while (std::fgets(buffer, sizeof(buffer), pipe) != nullptr)
    text += buffer;
  pclose(pipe);
  return text;
}

TEST(RiserAccuracy, NoiseFreeRiserIsReconstructedWithinTheVoxelSize) {
  test::ScratchDir dir;
  const auto mission = dir.path() / "riser";
  const auto out = dir.path() / "reconstruction";
  const auto sim = runCli("simulate --scene riser --noise none --out " + quoted(mission));
  ASSERT_EQ(sim.exit_code, 0) << sim.output;
  const auto rec = runCli("reconstruct " + quoted(mission) + " --out " + quoted(out));
  ASSERT_EQ(rec.exit_code, 0) << rec.output;
  std::ifstream in(out / "report.json");
  const auto report = nlohmann::json::parse(in);
  const auto& e = report.at("evaluation");
  // 2 cm voxels and 2 cm range bins: a voxel centre is within about a voxel of the surface.
  EXPECT_LE(e.at("accuracy_median_m").get<double>(), 0.02) << e.dump(2);
  EXPECT_LE(e.at("accuracy_p90_m").get<double>(), 0.05) << e.dump(2);
  EXPECT_GE(e.at("completeness").get<double>(), 0.90) << e.dump(2);

  // The stand-alone evaluate verb gives the same figures from the exported files.
  const auto eval = runCli("evaluate --json --reference " + quoted(mission / "ground_truth.ply") +
                           " --reconstruction " + quoted(out / "surface_points.ply") +
                           " --visible " + quoted(mission / "visible_points.ply"));
  ASSERT_EQ(eval.exit_code, 0) << eval.output;
  const auto j = nlohmann::json::parse(eval.output);
  EXPECT_NEAR(j.at("completeness").get<double>(), e.at("completeness").get<double>(), 1e-9);
  EXPECT_EQ(j.at("reconstructed_points"), report.at("surface_points"));

  // The mesh: distance from its vertices to the ground truth.
  const auto& mesh = report.at("mesh_evaluation");
  EXPECT_LE(mesh.at("accuracy_median_m").get<double>(), 0.02) << mesh.dump(2);
  EXPECT_LE(mesh.at("accuracy_p90_m").get<double>(), 0.05) << mesh.dump(2);

  // Other tools open the deliverables: assimp (Debian's assimp-utils) for PLY, ASCII PLY,
  // STL and OBJ, with the vertex and face counts of our mesh.
  ASSERT_EQ(runCli("export " + quoted(out) + " --out " + quoted(out / "mesh.obj")).exit_code, 0);
  ASSERT_EQ(runCli("export " + quoted(out) + " --format ply-ascii --frame zup --out " +
                   quoted(out / "mesh_zup.ply"))
                .exit_code,
            0);
  const long vertices = report.at("mesh_vertices").get<long>();
  const long faces = report.at("mesh_triangles").get<long>();
  ASSERT_GT(faces, 1000);
  for (const char* file : {"mesh.ply", "mesh_zup.ply", "mesh.stl", "mesh.obj"}) {
    const std::string text = commandOutput("assimp info " + quoted(out / file));
    std::smatch match;
    ASSERT_TRUE(std::regex_search(text, match, std::regex("Faces:\\s+(\\d+)"))) << file << text;
    EXPECT_EQ(std::stol(match[1]), faces) << file;
    if (std::string(file).find(".ply") != std::string::npos) {
      ASSERT_TRUE(std::regex_search(text, match, std::regex("Vertices:\\s+(\\d+)"))) << text;
      EXPECT_EQ(std::stol(match[1]), vertices) << file;
    }
  }

  // OctoMap's own bt2vrml reads the exported occupancy tree.
  if (std::system("command -v bt2vrml > /dev/null 2>&1") == 0) {
    const std::string command = "bt2vrml " + quoted(out / "map.bt") + " 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    std::string text;
    char buffer[512];
    while (std::fgets(buffer, sizeof(buffer), pipe) != nullptr)
      text += buffer;
    ASSERT_EQ(pclose(pipe), 0) << text;
    std::smatch m;
    ASSERT_TRUE(std::regex_search(text, m, std::regex("Finished writing (\\d+) voxels"))) << text;
    EXPECT_GT(std::stol(m[1]), 1000);
  } else {
    ADD_FAILURE() << "bt2vrml (Debian's octomap-tools) is not installed";
  }
}

TEST(RiserAccuracy, NoisyRiserWithTheDefaultDetectorKeepsItsAccuracy) {
  test::ScratchDir dir;
  const auto mission = dir.path() / "riser";
  const auto empty = dir.path() / "empty";
  const auto noise = dir.path() / "noise.yaml";
  ASSERT_EQ(runCli("simulate --scene riser --out " + quoted(mission)).exit_code, 0);
  ASSERT_EQ(
      runCli("simulate --scene riser --empty-water --seed 99 --out " + quoted(empty)).exit_code, 0);
  const auto model = runCli("noise-model " + quoted(empty) + " --out " + quoted(noise));
  ASSERT_EQ(model.exit_code, 0) << model.output;
  const auto out = dir.path() / "reconstruction";
  const auto rec = runCli("reconstruct " + quoted(mission) + " --noise-model " + quoted(noise) +
                          " --out " + quoted(out));
  ASSERT_EQ(rec.exit_code, 0) << rec.output;
  std::ifstream in(out / "report.json");
  const auto report = nlohmann::json::parse(in);
  EXPECT_EQ(report.at("detector"), "ztest");
  const auto& e = report.at("evaluation");
  EXPECT_GE(e.at("fscore").get<double>(), 0.85) << e.dump(2);
  EXPECT_LE(e.at("accuracy_median_m").get<double>(), 0.02) << e.dump(2);
  EXPECT_LE(e.at("accuracy_p90_m").get<double>(), 0.05) << e.dump(2);
}

}  // namespace
}  // namespace sonarcarve
