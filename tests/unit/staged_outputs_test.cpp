// A run's outputs written apart and moved in once complete (io/run/staged_outputs.h), and the
// folders a failed run made removed again (removeCreatedFolders, io/files/output_folder.h).
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>

#include "common/error.h"
#include "io/files/atomic_file.h"
#include "io/files/output_folder.h"
#include "io/run/staged_outputs.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

using test::readText;
using test::ScratchDir;

void writeText(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

TEST(StagedOutputs, AFileIsInTheFolderOnlyOnceMovedAndTheStagingGoesAway) {
  const ScratchDir dir;
  writeText(dir.path() / "report.json", "earlier");
  std::filesystem::path staging;
  {
    const StagedOutputs staged(dir.path());
    staging = staged.staging();
    EXPECT_EQ(staging.parent_path(), dir.path());
    writeFileAtomically(staging / "report.json", "this run");
    writeFileAtomically(staging / "mesh.ply", "unfinished");
    EXPECT_EQ(readText(dir.path() / "report.json"), "earlier");
    staged.publish("report.json");
    EXPECT_EQ(readText(dir.path() / "report.json"), "this run");
    EXPECT_EQ(staged.outputName((staging / "mesh.ply").string()),
              (dir.path() / "mesh.ply").string());
  }
  EXPECT_FALSE(std::filesystem::exists(staging));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "mesh.ply"));  // never moved in
}

TEST(StagedOutputs, WritesThroughALinkAndRefusesAFifo) {
  const ScratchDir dir;
  std::filesystem::create_directories(dir.path() / "elsewhere");
  writeText(dir.path() / "elsewhere" / "mesh.ply", "earlier");
  std::filesystem::create_symlink(dir.path() / "elsewhere" / "mesh.ply", dir.path() / "mesh.ply");
  ASSERT_EQ(::mkfifo((dir.path() / "map.bt").c_str(), 0600), 0);
  const StagedOutputs staged(dir.path());
  writeFileAtomically(staged.staging() / "mesh.ply", "new");
  writeFileAtomically(staged.staging() / "map.bt", "new");
  staged.publish("mesh.ply");
  EXPECT_TRUE(std::filesystem::is_symlink(dir.path() / "mesh.ply"));
  EXPECT_EQ(readText(dir.path() / "elsewhere" / "mesh.ply"), "new");
  test::expectError([&] { staged.publish("map.bt"); }, {"map.bt", "is a FIFO"});
  EXPECT_TRUE(std::filesystem::is_fifo(dir.path() / "map.bt"));
}

TEST(StagedOutputs, RemovesTheStagingOfAKilledRunButNotOfALiveOne) {
  const ScratchDir dir;
  // pid 1 is alive; no process has a pid above the kernel's largest (4194304).
  const auto alive = dir.path() / (std::string(StagedOutputs::kPrefix) + "1");
  const auto gone = dir.path() / (std::string(StagedOutputs::kPrefix) + "999999999");
  const auto users = dir.path() / (std::string(StagedOutputs::kPrefix) + "notes");
  for (const auto& folder : {alive, gone, users}) {
    std::filesystem::create_directories(folder);
    writeText(folder / "surface_points.ply", "x");
  }
  const StagedOutputs staged(dir.path());
  EXPECT_TRUE(std::filesystem::exists(alive));
  EXPECT_FALSE(std::filesystem::exists(gone));
  EXPECT_TRUE(std::filesystem::exists(users));
}

TEST(OutputFolder, AFailedRunRemovesTheFoldersItMadeAndNothingElse) {
  const ScratchDir dir;
  const auto out = dir.path() / "a" / "b" / "out";
  const std::vector<std::filesystem::path> created = prepareOutputFolder(out);
  ASSERT_EQ(created.size(), 3u);
  EXPECT_EQ(created.front(), dir.path() / "a");
  EXPECT_EQ(created.back(), out);
  EXPECT_EQ(removeCreatedFolders(created, false),
            (std::vector{out, out.parent_path(), dir.path() / "a"}));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "a"));
  EXPECT_TRUE(std::filesystem::exists(dir.path()));

  // What the run wrote stays unless the command says its partial output is no result.
  const auto again = prepareOutputFolder(out);
  writeText(out / "frame.png", "partial");
  EXPECT_TRUE(removeCreatedFolders(again, false).empty());
  EXPECT_TRUE(std::filesystem::exists(out / "frame.png"));
  EXPECT_EQ(removeCreatedFolders(again, true).size(), 3u);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "a"));

  // A folder that existed, or a parent that holds something else, is never removed.
  std::filesystem::create_directories(out);
  EXPECT_TRUE(prepareOutputFolder(out).empty());
  std::filesystem::remove_all(dir.path() / "a");
  const auto chain = prepareOutputFolder(out);
  writeText(out.parent_path() / "notes.txt", "the user's");
  EXPECT_EQ(removeCreatedFolders(chain, true), std::vector{out});
  EXPECT_TRUE(std::filesystem::exists(out.parent_path() / "notes.txt"));
}

}  // namespace
}  // namespace sonarcarve
