// ARIS recordings: the real recording in tests/data/aris against the values of its README,
// and empty, truncated and corrupt copies of it.
#include <gtest/gtest.h>

#include <cmath>

#include "common/angles.h"
#include "common/error.h"
#include "io/aris/aris_file.h"
#include "io/files/frame_png.h"
#include "io/frame_source.h"
#include "io/import.h"
#include "io/mission/mission.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

using test::expectError;

std::filesystem::path arisFixture() {
  return test::testData("aris/sample.aris");
}

std::string fixtureBytes() {
  return test::readText(arisFixture());
}

std::filesystem::path writeBytes(const std::filesystem::path& path, const std::string& bytes) {
  test::writeText(path, bytes);
  return path;
}

void putU32(std::string& bytes, std::size_t at, std::uint32_t value) {
  for (std::size_t i = 0; i < 4; ++i) {
    bytes[at + i] = static_cast<char>((value >> (8 * i)) & 0xFFU);
  }
}

constexpr std::size_t kFrame0 = 1024;
constexpr std::size_t kFrameBytes = 1024 + 48 * 2000;

TEST(ArisFixture, DecodesTheRealRecordingAsItsReadmeSays) {
  ASSERT_TRUE(looksLikeArisFile(arisFixture()));
  const ArisFile file = ArisFile::open(arisFixture());
  ASSERT_EQ(file.frames().size(), 6u);
  EXPECT_TRUE(file.problems().empty());
  const std::uint64_t times[] = {1371198079122519, 1371198079274984, 1371198079427694,
                                 1371198079580374, 1371198079733084, 1371198079886496};
  for (std::size_t k = 0; k < 6; ++k) {
    const ArisFrameInfo& f = file.frames()[k];
    EXPECT_EQ(f.frame_index, k);
    EXPECT_EQ(f.time_us, times[k]);
    EXPECT_EQ(f.ping_mode, 1u);
    EXPECT_EQ(f.beams, 48u);
    EXPECT_EQ(f.samples_per_beam, 2000u);
    EXPECT_EQ(f.sample_period_us, 14u);
    EXPECT_EQ(f.sample_start_delay_us, 4593u);
    EXPECT_NEAR(f.sound_speed_mps, 1435.9333, 1e-3);
    EXPECT_TRUE(f.large_lens);
    EXPECT_TRUE(f.reordered);
    EXPECT_EQ(f.depth_m, 0.0F);
    EXPECT_EQ(f.heading_deg, 0.0F);
  }
  EXPECT_NEAR(file.frames()[0].windowStart(), 3.2976, 1e-4);
  EXPECT_NEAR(file.frames()[0].windowEnd(), 23.4007, 1e-4);
}

TEST(ArisFixture, ImageColumnsRunPortToStarboardWithArisBeamZeroOnTheRight) {
  const ArisFile file = ArisFile::open(arisFixture());
  const cv::Mat image = file.image(0);
  ASSERT_EQ(image.rows, 2000);
  ASSERT_EQ(image.cols, 48);
  EXPECT_EQ(image.type(), CV_32F);
  EXPECT_NEAR(cv::mean(image)[0], 90.993, 1e-3);
  EXPECT_EQ(image.at<float>(0, 47), 119.0F);  // ARIS beam 0: starboard, our last column
  EXPECT_EQ(image.at<float>(0, 0), 131.0F);   // ARIS beam 47: port
}

TEST(ArisFixture, OpensThroughTheRegistryWithTheTelephotoTable) {
  const Mission mission = openMission(arisFixture());
  EXPECT_EQ(mission.source->kind(), "ARIS recording");
  ASSERT_EQ(mission.frames.size(), 6u);
  EXPECT_NEAR(mission.frames[0].time_s, 1371198079.122519, 1e-6);
  EXPECT_EQ(mission.sonar.cols(), 48);
  EXPECT_EQ(mission.sonar.rows(), 2000);
  EXPECT_NEAR(mission.sonar.range().min_m, 3.2976, 1e-4);
  EXPECT_NEAR(mission.sonar.range().maxRange(), 23.4007, 1e-4);
  EXPECT_NEAR(radToDeg(mission.sonar.bearings().centre(0)), -6.742, 1e-9);
  EXPECT_NEAR(radToDeg(mission.sonar.bearings().centre(47)), 6.742, 1e-9);
  EXPECT_NEAR(radToDeg(mission.sonar.bearings().centre(24)), 0.154, 1e-9);
  const Frame frame = loadFrame(mission, 5);
  EXPECT_EQ(frame.image.rows, 2000);
  EXPECT_NEAR(frame.time_s, 1371198079.886496, 1e-6);
}

// ARIS samples are decibels (0..255 for 0..80 dB): the engine gets the echo's power, so that
// dividing by the beam's power gain and the keep level's ratio of powers mean what they say.
TEST(ArisFixture, FramesLoadAsThePowerOfTheirDecibelSamples) {
  const Mission mission = openMission(arisFixture());
  EXPECT_EQ(mission.sonar.intensityScale(), IntensityScale::decibel(80.0, 255.0));
  const cv::Mat bytes = ArisFile::open(arisFixture()).image(0);
  const cv::Mat power = loadFrame(mission, 0).image;
  ASSERT_EQ(power.size(), bytes.size());
  const double byte119 = std::pow(10.0, 119.0 * 80.0 / 2550.0);
  const double byte131 = std::pow(10.0, 131.0 * 80.0 / 2550.0);
  EXPECT_NEAR(power.at<float>(0, 47), byte119, 1e-5 * byte119);  // float precision
  EXPECT_NEAR(power.at<float>(0, 0), byte131, 1e-5 * byte131);
  double worst = 0.0;
  for (int r = 0; r < bytes.rows; r += 7) {
    for (int c = 0; c < bytes.cols; ++c) {
      const float byte = bytes.at<float>(r, c);
      if (byte == 0.0f) {  // the bottom of the scale: no echo
        ASSERT_EQ(power.at<float>(r, c), 0.0f);
        continue;
      }
      const double expected = std::pow(10.0, byte * 8.0 / 255.0);
      worst = std::max(worst, std::abs(power.at<float>(r, c) / expected - 1.0));
    }
  }
  EXPECT_LT(worst, 1e-5);  // float precision, far under the 7.5 % of one count
}

// Imported into a mission folder, the frames keep the sonar's bytes (80 dB of power would not
// fit a 16-bit PNG) and the folder says they are decibels: it loads the same power.
TEST(ArisFixture, ImportKeepsTheBytesAndTheirScale) {
  test::ScratchDir dir;
  ImportRequest request;
  request.log = arisFixture();
  request.out = dir.path() / "m";
  SilentProgress progress;
  importRecordingToMission(request, OpenOptions{}, progress);
  EXPECT_NE(test::readText(request.out / "mission.yaml")
                .find("intensity: {scale: decibel, full_scale_db: 80, full_scale_count: 255}"),
            std::string::npos);
  const cv::Mat bytes = ArisFile::open(arisFixture()).image(3);
  EXPECT_EQ(cv::norm(readFramePng(request.out / "frames/000003.png"), bytes, cv::NORM_INF), 0.0);
  const Mission imported = openMission(request.out);
  const Mission in_place = openMission(arisFixture());
  EXPECT_EQ(imported.sonar.intensityScale(), in_place.sonar.intensityScale());
  EXPECT_EQ(cv::norm(loadFrame(imported, 3).image, loadFrame(in_place, 3).image, cv::NORM_INF),
            0.0);
}

TEST(ArisErrors, EmptyAndShortFilesNameTheFileAndWhatWasExpected) {
  const test::ScratchDir dir;
  const auto empty = writeBytes(dir.path() / "empty.aris", "");
  expectError([&] { ArisFile::open(empty); },
              {"empty.aris", "byte 0", "shorter than the 1024-byte ARIS file header"});
  const auto header_only = writeBytes(dir.path() / "header.aris", fixtureBytes().substr(0, 1024));
  expectError([&] { ArisFile::open(header_only); },
              {"header.aris", "byte 1024", "no complete frame"});
}

TEST(ArisErrors, WrongMagicIsNotAnArisFile) {
  const test::ScratchDir dir;
  std::string bytes = fixtureBytes();
  putU32(bytes, 0, 0x12345678);
  const auto path = writeBytes(dir.path() / "magic.aris", bytes);
  EXPECT_FALSE(looksLikeArisFile(path));
  expectError([&] { ArisFile::open(path); },
              {"magic.aris", "byte 0", "expected version 0x05464444"});
}

TEST(ArisErrors, AbsurdFirstFrameFieldsAreErrorsNamingTheField) {
  const test::ScratchDir dir;
  const struct {
    std::size_t at;
    std::uint32_t value;
    const char* fragment;
  } cases[] = {{436, 99, "PingMode 99"},
               {468, 0xFFFFFFF0U, "SamplesPerBeam 4294967280"},
               {452, 0, "SamplePeriod 0"},
               {464, 0, "SoundSpeed"},
               {516, 0, "ReorderedSamples 0"}};
  for (const auto& c : cases) {
    std::string bytes = fixtureBytes();
    putU32(bytes, kFrame0 + c.at, c.value);
    const auto path = writeBytes(dir.path() / "bad.aris", bytes);
    expectError([&] { ArisFile::open(path); }, {"bad.aris", "frame 0, byte 1024", c.fragment});
  }
}

TEST(ArisErrors, TruncatedOrCorruptLaterFramesAreLeftOutAndReported) {
  const test::ScratchDir dir;
  const std::string bytes = fixtureBytes();
  const auto cut = writeBytes(dir.path() / "cut.aris", bytes.substr(0, bytes.size() - 10));
  const ArisFile cut_file = ArisFile::open(cut);
  EXPECT_EQ(cut_file.frames().size(), 5u);
  ASSERT_EQ(cut_file.problems().size(), 1u);
  EXPECT_NE(cut_file.problems()[0].find("frame 5"), std::string::npos);
  EXPECT_NE(cut_file.problems()[0].find("truncated samples"), std::string::npos);

  std::string corrupt = bytes;
  putU32(corrupt, kFrame0 + 3 * kFrameBytes + 468, 1000);  // frame 3: other sample count
  const auto bad = writeBytes(dir.path() / "corrupt.aris", corrupt);
  const Mission mission = openMission(bad);
  EXPECT_EQ(mission.frames.size(), 3u);
  bool reported = false;
  for (const std::string& w : mission.warnings) {
    reported = reported || (w.find("frame 3") != std::string::npos &&
                            w.find("geometry differs") != std::string::npos);
  }
  EXPECT_TRUE(reported);
}

}  // namespace
}  // namespace sonarcarve
