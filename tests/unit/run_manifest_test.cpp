// The run manifest of an output folder (io/run/run_manifest.h): what it records, and that the
// files of an earlier run that this run did not rewrite are gone when it ends, complete or not.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "io/run/run_manifest.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

void writeText(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

nlohmann::json readManifest(const std::filesystem::path& folder) {
  return nlohmann::json::parse(test::readText(folder / RunManifest::kFileName));
}

const std::vector<std::string> kKnown = {"mesh.ply", "report.json"};

TEST(RunManifest, RecordsTheRunItsStatusAndEachFileWithItsSize) {
  const test::ScratchDir dir;
  RunManifest manifest(dir.path(), {"sonarcarve-cli", "reconstruct", "m", "--out", "o"}, kKnown);
  nlohmann::json j = readManifest(dir.path());
  EXPECT_EQ(j["status"], "running");
  EXPECT_EQ(j["files"].size(), 0u);
  EXPECT_FALSE(j.contains("finished_utc"));
  writeText(dir.path() / "report.json", "{}\n");
  manifest.wrote("report.json");
  manifest.finish("complete");
  j = readManifest(dir.path());
  EXPECT_EQ(j["format"], "sonarcarve run manifest 1");
  EXPECT_EQ(j["status"], "complete");
  EXPECT_EQ(j["version"], SONARCARVE_VERSION);
  EXPECT_EQ(j["arguments"][1], "reconstruct");
  EXPECT_EQ(j["arguments"].size(), 5u);
  ASSERT_EQ(j["files"].size(), 1u);
  EXPECT_EQ(j["files"][0]["name"], "report.json");
  EXPECT_EQ(j["files"][0]["bytes"], 3);
  EXPECT_EQ(j["started_utc"].get<std::string>().size(), 20u);  // 2026-01-02T03:04:05Z
  EXPECT_TRUE(j.contains("finished_utc"));
  EXPECT_TRUE(manifest.removed().empty());
}

TEST(RunManifest, EarlierFilesNotRewrittenAreRemovedOthersKept) {
  const test::ScratchDir dir;
  writeText(dir.path() / "mesh.ply", "old mesh");       // a known output, no manifest needed
  writeText(dir.path() / "extra.bin", "old extra");     // listed by the earlier manifest
  writeText(dir.path() / "report.json", "old report");  // rewritten by this run
  writeText(dir.path() / "notes.txt", "the user's");    // neither: kept
  writeText(dir.path() / RunManifest::kFileName,
            R"({"status": "complete", "files": [{"name": "extra.bin", "bytes": 9}]})");
  RunManifest manifest(dir.path(), {"cli"}, kKnown);
  EXPECT_EQ(readManifest(dir.path())["earlier_files"],
            nlohmann::json({"extra.bin", "mesh.ply", "report.json"}));
  writeText(dir.path() / "report.json", "new report");
  manifest.wrote("report.json");
  manifest.finish("complete");
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "mesh.ply"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "extra.bin"));
  EXPECT_EQ(test::readText(dir.path() / "report.json"), "new report");
  EXPECT_EQ(test::readText(dir.path() / "notes.txt"), "the user's");
  EXPECT_EQ(manifest.removed().size(), 2u);
  EXPECT_FALSE(readManifest(dir.path()).contains("earlier_files"));
}

TEST(RunManifest, AFailedRunLeavesOnlyItsOwnFilesAndSaysWhy) {
  const test::ScratchDir dir;
  writeText(dir.path() / "mesh.ply", "old mesh");
  RunManifest manifest(dir.path(), {"cli"}, kKnown);
  manifest.finish("failed", "out/mesh.ply: byte 0: write failed");
  const nlohmann::json j = readManifest(dir.path());
  EXPECT_EQ(j["status"], "failed");
  EXPECT_EQ(j["error"], "out/mesh.ply: byte 0: write failed");
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "mesh.ply"));
}

TEST(RunManifest, ARunKilledWhileWritingIsCleanedByTheNext) {
  const test::ScratchDir dir;
  writeText(dir.path() / "old.bin", "old");
  writeText(dir.path() / RunManifest::kFileName,
            R"({"status": "running", "files": [], "earlier_files": ["old.bin"]})");
  RunManifest manifest(dir.path(), {"cli"}, kKnown);
  manifest.finish("complete");
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "old.bin"));
}

TEST(RunManifest, NamesOutsideTheFolderOrUnreadableManifestsRemoveNothing) {
  const test::ScratchDir dir;
  std::filesystem::create_directories(dir.path() / "out");
  writeText(dir.path() / "outside.txt", "not the run's");
  writeText(dir.path() / "out" / RunManifest::kFileName,
            R"({"files": ["../outside.txt", "/etc/hostname", "..", 7, {"name": null}]})");
  EXPECT_EQ(filesListedInManifest(dir.path() / "out" / RunManifest::kFileName),
            std::vector<std::string>{});
  RunManifest(dir.path() / "out", {"cli"}, kKnown).finish("complete");
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "outside.txt"));
  writeText(dir.path() / "out" / RunManifest::kFileName, "{ not json");
  EXPECT_EQ(filesListedInManifest(dir.path() / "out" / RunManifest::kFileName),
            std::vector<std::string>{});
}

}  // namespace
}  // namespace sonarcarve
