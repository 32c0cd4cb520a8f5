// Every way a mission can be broken gets an error naming the file, the place and what was
// expected; a broken frame is reported alone and the rest of the mission stays usable.
#include <gtest/gtest.h>

#include <functional>
#include <opencv2/imgcodecs.hpp>

#include "common/error.h"
#include "io/mission/mission.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

using test::readText;
using test::writeText;

class MissionErrors : public ::testing::Test {
 protected:
  void SetUp() override { mission_ = test::copyExampleMission(dir_.path()); }

  // Replaces the first occurrence of `from` with `to` in a mission file.
  void edit(const std::string& file, const std::string& from, const std::string& to) {
    std::string text = readText(mission_ / file);
    const auto at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    writeText(mission_ / file, text);
  }

  // The mission must fail to read with an error containing every fragment.
  void expectReadError(const std::vector<std::string>& fragments) {
    try {
      readMission(mission_);
      ADD_FAILURE() << "mission read without error";
    } catch (const Error& e) {
      for (const auto& fragment : fragments) {
        EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos)
            << "'" << fragment << "' not in: " << e.what();
      }
    }
  }

  test::ScratchDir dir_;
  std::filesystem::path mission_;
};

TEST_F(MissionErrors, MissingFolderOrYaml) {
  std::filesystem::remove(mission_ / "mission.yaml");
  expectReadError({"mission.yaml: not found: expected a YAML file"});
  EXPECT_THROW(readMission(dir_.path() / "nowhere"), Error);
}

TEST_F(MissionErrors, EmptyAndTruncatedYaml) {
  writeText(mission_ / "mission.yaml", "");
  expectReadError({"mission.yaml", "expected a YAML mapping"});
  const std::string full = readText(test::exampleMission() / "mission.yaml");
  writeText(mission_ / "mission.yaml", full.substr(0, full.find("sonar:") + 30));
  expectReadError({"mission.yaml"});
  writeText(mission_ / "mission.yaml", "format: [unclosed\n");
  expectReadError({"mission.yaml", "line 2", "not valid YAML"});
}

TEST_F(MissionErrors, UnknownFormatOrVersion) {
  edit("mission.yaml", "version: 1", "version: 7");
  expectReadError({"mission.yaml", "line 3", "unknown format version 7", "reads 1"});
  edit("mission.yaml", "format: sonarcarve-mission", "format: something-else");
  expectReadError({"mission.yaml", "line 2", "expected 'sonarcarve-mission'"});
}

TEST_F(MissionErrors, MissingOrInvalidSonarFields) {
  edit("mission.yaml", "bins: 200", "binz: 200");
  expectReadError({"mission.yaml", "line 7", "sonar.range.bins: missing"});
}

TEST_F(MissionErrors, InvalidSonarValue) {
  edit("mission.yaml", "resolution_m: 0.025", "resolution_m: -0.025");
  expectReadError({"mission.yaml", "sonar.range.resolution_m: expected 1e-04 to 10 m, got -0.025"});
}

TEST_F(MissionErrors, InvalidIntensityScale) {
  const std::string original = readText(mission_ / "mission.yaml");
  const std::pair<std::string, std::string> cases[] = {
      {"{scale: decibels, full_scale_db: 80, full_scale_count: 255}",
       "sonar.intensity.scale: expected 'linear', 'decibel' or 'gamma'"},
      {"{scale: gamma, gamma: 12, full_scale_count: 255}",
       "sonar.intensity.gamma: expected 0.01 to 10, got 12"},
      {"{scale: gamma, gamma: 0.5}", "sonar.intensity.full_scale_count: missing"},
      {"{scale: decibel, full_scale_db: 0, full_scale_count: 255}",
       "sonar.intensity.full_scale_db: expected 1 to 200 dB, got 0"},
      {"{scale: decibel, full_scale_db: 80}", "sonar.intensity.full_scale_count: missing"},
      {"logarithmic", "sonar.intensity: expected 'linear' or a mapping"}};
  for (const auto& [intensity, message] : cases) {
    writeText(mission_ / "mission.yaml", original);
    edit("mission.yaml",
         "vertical_aperture_deg:", "intensity: " + intensity + "\n  vertical_aperture_deg:");
    expectReadError({"mission.yaml", message});
  }
  // An error in a field of the scale is reported at that field alone.
  writeText(mission_ / "mission.yaml", original);
  edit("mission.yaml",
       "vertical_aperture_deg:", "intensity: {scale: gamma, gamma: 0.5}\n  vertical_aperture_deg:");
  try {
    readMission(mission_);
    ADD_FAILURE() << "mission read without error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).find("gamma: sonar"), std::string::npos) << e.what();
  }
}

TEST_F(MissionErrors, InvalidHorizontalBeamWidth) {
  const std::string original = readText(mission_ / "mission.yaml");
  const std::pair<std::string, std::string> cases[] = {
      {"-1", "sonar.horizontal_beam_width_deg: expected 0.01 to 360 (excluded) degrees, got -1"},
      {"wide", "sonar.horizontal_beam_width_deg: expected a finite number"},
      {"400", "sonar.horizontal_beam_width_deg: expected 0.01 to 360 (excluded) degrees"},
      {"100", "sonar.horizontal_beam_width_deg: expected less than the field of view"}};
  for (const auto& [width, message] : cases) {
    writeText(mission_ / "mission.yaml", original);
    edit("mission.yaml", "vertical_aperture_deg:",
         "horizontal_beam_width_deg: " + width + "\n  vertical_aperture_deg:");
    expectReadError({"mission.yaml", message});
  }
}

TEST_F(MissionErrors, MissingNavigationFile) {
  std::filesystem::remove(mission_ / "nav.csv");
  expectReadError({"nav.csv: not found: expected a CSV table"});
}

TEST_F(MissionErrors, MissingNavigationColumn) {
  edit("nav.csv", "pitch_deg", "pitch");
  expectReadError({"nav.csv", "line 1", "missing column 'pitch_deg'"});
}

TEST_F(MissionErrors, NaNInNavigation) {
  edit("nav.csv", "100.25,0,0,10.05", "100.25,nan,0,10.05");
  expectReadError({"nav.csv", "line 3", "north_m", "finite number"});
}

TEST_F(MissionErrors, NavigationTimeGoingBackwards) {
  edit("nav.csv", "100.75,", "100.0,");
  expectReadError({"nav.csv", "line 4", "time goes backwards"});
}

TEST_F(MissionErrors, TruncatedNavigation) {
  const std::string nav = readText(mission_ / "nav.csv");
  writeText(mission_ / "nav.csv", nav.substr(0, nav.size() - 8));
  expectReadError({"nav.csv", "line 12", "expected 7 values"});
  writeText(mission_ / "nav.csv", "");
  expectReadError({"nav.csv", "file is empty"});
}

TEST_F(MissionErrors, FrameIndexTimeGoingBackwards) {
  edit("frames.csv", "101,example-sonar", "99,example-sonar");
  expectReadError({"frames.csv", "line 4", "time goes backwards"});
}

TEST_F(MissionErrors, BrokenFramesAreReportedOneByOneAndTheRestStillLoads) {
  const auto frames = mission_ / "frames";
  // frame 2: truncated; 4: empty; 6: another size; 8: missing.
  const std::string png = readText(frames / "000002.png");
  writeText(frames / "000002.png", png.substr(0, png.size() / 3));
  writeText(frames / "000004.png", "");
  std::filesystem::remove(frames / "000008.png");
  edit("frames.csv", "frames/000006.png", "frames/wrong_size.png");
  cv::Mat small(10, 10, CV_16U, cv::Scalar(5));
  ASSERT_TRUE(cv::imwrite((frames / "wrong_size.png").string(), small));

  const Mission m = readMission(mission_);
  const auto problems = checkFrames(m);
  ASSERT_EQ(problems.size(), 4u);
  EXPECT_EQ(problems[0].index, 2u);
  EXPECT_NE(problems[0].message.find("000002.png"), std::string::npos);
  EXPECT_NE(problems[0].message.find("truncated"), std::string::npos);
  EXPECT_EQ(problems[1].index, 4u);
  EXPECT_NE(problems[1].message.find("empty file"), std::string::npos);
  EXPECT_EQ(problems[2].index, 6u);
  EXPECT_NE(problems[2].message.find("expected 200 range bins x 64 beams"), std::string::npos);
  EXPECT_EQ(problems[3].index, 8u);
  EXPECT_NE(problems[3].message.find("000008.png"), std::string::npos);
  EXPECT_NO_THROW(loadFrame(m, 3));
  EXPECT_EQ(loadFrame(m, 9).image.rows, 200);
}

TEST_F(MissionErrors, FrameFromAnotherSonarIsRefused) {
  edit("frames.csv", "100.5,example-sonar", "100.5,other-sonar");
  const Mission m = readMission(mission_);
  const auto problems = checkFrames(m);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].index, 1u);
  EXPECT_NE(problems[0].message.find("other-sonar"), std::string::npos);
}

}  // namespace
}  // namespace sonarcarve
