// Sessions are recognised by what they say they are, not by their name.
#include <gtest/gtest.h>

#include "pipeline/param_diff.h"
#include "session/session_file.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

TEST(SessionFile, IsRecognisedByItsContentWhateverItsName) {
  test::ScratchDir dir;
  Session session;
  session.mission = test::exampleMission().string();
  const auto renamed = dir.path() / "survey notes.txt";
  saveSession(session, renamed);
  EXPECT_TRUE(looksLikeSessionFile(renamed));
  EXPECT_EQ(loadSession(renamed).mission, session.mission);

  EXPECT_FALSE(looksLikeSessionFile(test::exampleMission() / "mission.yaml"));
  EXPECT_FALSE(looksLikeSessionFile(test::exampleMission()));  // a folder
  EXPECT_FALSE(looksLikeSessionFile(dir.path() / "missing.sonarcarve"));
  const auto empty = dir.path() / "empty.sonarcarve";
  test::writeText(empty, "");
  EXPECT_FALSE(looksLikeSessionFile(empty));
}

// The run history round-trips with its parameters and figures; a session without one (every
// file written before it existed) loads with an empty history.
TEST(SessionFile, KeepsTheRunHistory) {
  test::ScratchDir dir;
  Session session;
  session.mission = "/data/riser";
  RunRecord first;
  first.started = "2026-11-24 23:10:05";
  first.frames = 98;
  first.occupied_voxels = 41234;
  first.surface_points = 9001;
  first.mesh_triangles = 20002;
  first.seconds = 9.75;
  RunRecord second = first;
  second.params.carve.voxel_size_m = 0.03;
  second.accuracy = RunAccuracy{0.943, 0.0053, 0.0134, 0.951, 0.932};
  session.runs = {first, second};
  const auto file = dir.path() / "history.sonarcarve";
  saveSession(session, file);
  const Session loaded = loadSession(file);
  ASSERT_EQ(loaded.runs.size(), 2u);
  EXPECT_EQ(loaded.runs[0].started, first.started);
  EXPECT_EQ(loaded.runs[0].surface_points, 9001u);
  EXPECT_EQ(loaded.runs[0].mesh_triangles, 20002u);
  EXPECT_DOUBLE_EQ(loaded.runs[0].seconds, 9.75);
  EXPECT_FALSE(loaded.runs[0].accuracy);
  EXPECT_DOUBLE_EQ(loaded.runs[1].params.carve.voxel_size_m, 0.03);
  ASSERT_TRUE(loaded.runs[1].accuracy);
  EXPECT_DOUBLE_EQ(loaded.runs[1].accuracy->fscore, 0.943);
  EXPECT_DOUBLE_EQ(loaded.runs[1].accuracy->completeness, 0.932);

  for (const char* old : {"full.sonarcarve", "minimal.sonarcarve"}) {
    EXPECT_TRUE(loadSession(test::testData("../fuzz/corpus/session") / old).runs.empty()) << old;
  }
  const auto broken = dir.path() / "broken.sonarcarve";
  test::writeText(broken,
                  "format: sonarcarve-session\nversion: 1\nmission: /m\nruns:\n  - frames: -3\n");
  test::expectError([&] { loadSession(broken); }, {"broken.sonarcarve", "runs[0].frames"});
}

// Two runs compared: only the parameters that differ, as a file writes them.
TEST(SessionFile, RunsComparedByTheParametersThatDiffer) {
  ReconstructionParams a;
  ReconstructionParams b;
  EXPECT_TRUE(differingParams(a, b).empty());
  b.carve.voxel_size_m = 0.03;
  b.noise_model = "/data/noise.yaml";
  const auto differences = differingParams(a, b);
  ASSERT_EQ(differences.size(), 2u);
  EXPECT_EQ(differences[0].key, "noise_model");
  EXPECT_EQ(differences[0].a, "");
  EXPECT_EQ(differences[0].b, "/data/noise.yaml");
  EXPECT_EQ(differences[1].key, "voxel_size_m");
  EXPECT_EQ(differences[1].unit, "m");
  EXPECT_EQ(differences[1].b, "0.03");
}

}  // namespace
}  // namespace sonarcarve
