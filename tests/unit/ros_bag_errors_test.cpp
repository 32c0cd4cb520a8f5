// ROS 2 bags that are broken: empty, cut short, corrupt, of the wrong types, or ambiguous. Each
// gives an Error naming the file, the place and what was expected; a corrupt message or chunk
// is skipped and reported, the rest read.
#include <gtest/gtest.h>

#include <sqlite3.h>

#include <fstream>

#include "io/frame_source.h"
#include "io/rosbag/bag_writer.h"
#include "io/rosbag/mcap_writer.h"
#include "io/rosbag/ros_bag.h"
#include "io/rosbag/ros_messages.h"
#include "support/bag_fixtures.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

std::string readBytes(const std::filesystem::path& path) {
  return test::readText(path);
}

std::filesystem::path writeMissionBag(const test::ScratchDir& dir, BagFormat format,
                                      const std::string& name, std::size_t frames = 4,
                                      std::size_t chunk_bytes = 4000) {
  BagWriteOptions options;
  options.format = format;
  options.chunk_bytes = chunk_bytes;
  const auto path = dir.path() / name;
  writeRosBag(test::memoryMission(frames, test::countsPattern), path, options);
  return path;
}

bool anyContains(const std::vector<std::string>& lines, const std::string& text) {
  for (const std::string& line : lines) {
    if (line.find(text) != std::string::npos) {
      return true;
    }
  }
  return false;
}

TEST(RosBagErrors, AnEmptyOrForeignFileIsNotTakenForABag) {
  const test::ScratchDir dir;
  test::writeText(dir.path() / "empty.mcap", "");
  EXPECT_FALSE(looksLikeRosBag(dir.path() / "empty.mcap"));
  test::expectError([&] { openMcapBag(dir.path() / "empty.mcap"); },
                    {"empty.mcap", "byte 0", "empty file: expected an MCAP bag"});
  test::writeText(dir.path() / "text.mcap", "this is not a bag at all");
  test::expectError([&] { openMcapBag(dir.path() / "text.mcap"); },
                    {"text.mcap", "byte 0", "expected the magic"});
  // A SQLite3 database that is not a bag (no messages table) is not recognised.
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open((dir.path() / "other.db3").c_str(), &db), SQLITE_OK);
  sqlite3_exec(db, "CREATE TABLE things(id INTEGER)", nullptr, nullptr, nullptr);
  sqlite3_close(db);
  EXPECT_FALSE(looksLikeRosBag(dir.path() / "other.db3"));
  test::expectError([&] { openSqliteBag(dir.path() / "other.db3"); },
                    {"other.db3", "no such table: topics", "expected a rosbag2 bag"});
}

TEST(RosBagErrors, AnMcapFileCutShortKeepsItsCompleteFramesAndSaysWhere) {
  const test::ScratchDir dir;
  const auto whole = writeMissionBag(dir, BagFormat::Mcap, "whole.mcap");
  const std::string bytes = readBytes(whole);
  const auto cut = dir.path() / "cut.mcap";
  test::writeText(cut, bytes.substr(0, bytes.size() * 6 / 10));  // as after a crash
  const Mission mission = openMission(cut);
  EXPECT_GE(mission.frames.size(), 1U);
  EXPECT_LT(mission.frames.size(), 4U);
  EXPECT_TRUE(anyContains(mission.warnings, "cut short")) << mission.warnings.front();
  EXPECT_TRUE(anyContains(mission.warnings, "cut.mcap: byte "));
  for (std::size_t k = 0; k < mission.frames.size(); ++k) {
    EXPECT_NO_THROW(loadFrame(mission, k));
  }
  // Cut inside the first records: nothing to read is an error, not an empty mission.
  test::writeText(cut, bytes.substr(0, 30));
  test::expectError([&] { openMission(cut); }, {"cut.mcap", "no Channel record"});
}

TEST(RosBagErrors, ACorruptChunkIsSkippedAndReportedTheOthersRead) {
  const test::ScratchDir dir;
  const auto path = writeMissionBag(dir, BagFormat::Mcap, "corrupt.mcap");
  std::string bytes = readBytes(path);
  // Flip bytes in the middle of the file: inside one frame's zstd chunk.
  for (std::size_t i = bytes.size() / 2; i < bytes.size() / 2 + 16; ++i) {
    bytes[i] = static_cast<char>(bytes[i] ^ 0x5A);
  }
  test::writeText(path, bytes);
  const Mission mission = openMission(path);
  EXPECT_EQ(mission.frames.size(), 3U);
  EXPECT_TRUE(anyContains(mission.warnings, "corrupt.mcap: chunk at byte ")) << mission.warnings[0];
  EXPECT_TRUE(anyContains(mission.warnings, "chunk skipped"));
}

TEST(RosBagErrors, ACorruptMessageIsSkippedAndReportedNotFatal) {
  const test::ScratchDir dir;
  const auto path = writeMissionBag(dir, BagFormat::McapUnchunked, "message.mcap");
  std::string bytes = readBytes(path);
  // The second sonar message's image.data length (40 ranges x 24 beams x 2 bytes), after its
  // header's frame_id "sonar" (a CDR string: length 6, the text and a NUL).
  const std::string frame_id("\x06\x00\x00\x00sonar\x00", 10);
  const auto second = bytes.find(frame_id, bytes.find(frame_id) + 1);
  ASSERT_NE(second, std::string::npos);
  const std::uint32_t size = 40 * 24 * 2;
  const auto at = bytes.find(std::string(reinterpret_cast<const char*>(&size), 4), second);
  ASSERT_NE(at, std::string::npos);
  const std::uint32_t huge = 0x7FFFFFFF;
  bytes.replace(at, 4, std::string(reinterpret_cast<const char*>(&huge), 4));
  test::writeText(path, bytes);
  const Mission mission = openMission(path);
  EXPECT_EQ(mission.frames.size(), 3U);
  EXPECT_TRUE(anyContains(mission.warnings, "image.data claims 2147483647 elements"))
      << mission.warnings.front();
  EXPECT_TRUE(anyContains(mission.warnings, "message.mcap: message "));
  EXPECT_TRUE(anyContains(mission.warnings, "(message skipped)"));
}

// A bag with one topic of `type` whose messages are `payload`.
std::filesystem::path oneTopicBag(const test::ScratchDir& dir, const std::string& name,
                                  const std::string& topic, const std::string& type,
                                  const std::vector<std::uint8_t>& payload) {
  McapWriter writer(McapChunks::None, 1 << 20);
  writer.addSchema(1, type, "");
  writer.addChannel(1, 1, topic);
  writer.addMessage(1, 10, 10, payload);
  const auto bytes = writer.finish();
  const auto path = dir.path() / name;
  test::writeText(path, std::string(bytes.begin(), bytes.end()));
  return path;
}

TEST(RosBagErrors, ABagWithoutSonarImagesNamesItsTopicsAndTheTypeExpected) {
  const test::ScratchDir dir;
  const auto path =
      oneTopicBag(dir, "camera.mcap", "/camera/image", "sensor_msgs/msg/Image", {0, 1, 0, 0});
  test::expectError(
      [&] { openMission(path); },
      {"camera.mcap", "no sonar topic", "expected marine_acoustic_msgs/msg/ProjectedSonarImage",
       "/camera/image (sensor_msgs/msg/Image)"});
}

TEST(RosBagErrors, MessagesThatAreNotTheirSchemasTypeAreAClearError) {
  const test::ScratchDir dir;
  RosPoseMsg pose;
  pose.header.frame_id = "map";
  const auto path =
      oneTopicBag(dir, "schema.mcap", "/sonar", kProjectedSonarImageType, encodeOdometry(pose));
  test::expectError(
      [&] { openMission(path); },
      {"schema.mcap", "topic /sonar", "no readable sonar message", "message 0", "CDR byte",
       "bytes after the last field of "
       "marine_acoustic_msgs/msg/ProjectedSonarImage"});
}

TEST(RosBagErrors, TwoSonarTopicsNeedAChoiceAndTheChoiceIsRead) {
  const test::ScratchDir dir;
  BagWriteOptions options;
  options.format = BagFormat::Db3;
  const auto path = dir.path() / "two.db3";
  writeRosBag(test::memoryMission(2, test::countsPattern), path, options);
  // A second sonar topic: the same rows under another topic id.
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(db,
                         "INSERT INTO topics VALUES(9, '/sonar/other', "
                         "'marine_acoustic_msgs/msg/ProjectedSonarImage', 'cdr', '');"
                         "INSERT INTO messages(topic_id, timestamp, data) SELECT 9, timestamp, "
                         "data FROM messages WHERE topic_id = 1;",
                         nullptr, nullptr, nullptr),
            SQLITE_OK);
  sqlite3_close(db);
  test::expectError([&] { openMission(path); },
                    {"two.db3", "2 sonar topics", "/sonar/image", "/sonar/other", "--sonar-topic"});
  OpenOptions choice;
  choice.bag.sonar_topic = "/sonar/other";
  EXPECT_EQ(openMission(path, choice).frames.size(), 2U);
  choice.bag.sonar_topic = "/odometry";
  test::expectError([&] { openMission(path, choice); },
                    {"two.db3", "topic /odometry", "nav_msgs/msg/Odometry (--sonar-topic)",
                     "expected marine_acoustic_msgs/msg/ProjectedSonarImage"});
  choice.bag.sonar_topic = "/nothing";
  test::expectError([&] { openMission(path, choice); }, {"no topic /nothing (--sonar-topic)"});
}

TEST(RosBagErrors, ATruncatedOrCorruptDb3IsAnErrorNamingTheFile) {
  const test::ScratchDir dir;
  const auto path = writeMissionBag(dir, BagFormat::Db3, "bag.db3");
  const std::string bytes = readBytes(path);
  const auto cut = dir.path() / "cut.db3";
  test::writeText(cut, bytes.substr(0, bytes.size() / 3));
  try {
    const Mission mission = openMission(cut);
    // SQLite may still read the rows it has: then the frames that are missing are reported.
    for (std::size_t k = 0; k < mission.frames.size(); ++k) {
      loadFrame(mission, k);
    }
    ADD_FAILURE() << "a third of a bag read without error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("cut.db3"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("SQLite"), std::string::npos) << e.what();
  }
  // A corrupt first page (the schema) is not taken for a bag.
  std::string corrupt = bytes;
  for (std::size_t i = 100; i < 600; ++i) {
    corrupt[i] = static_cast<char>(0xA5);
  }
  test::writeText(dir.path() / "corrupt.db3", corrupt);
  test::expectError([&] { openSqliteBag(dir.path() / "corrupt.db3"); }, {"corrupt.db3", "SQLite"});
}

}  // namespace
}  // namespace sonarcarve
