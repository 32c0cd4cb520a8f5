#include <gtest/gtest.h>

#include "common/angles.h"
#include "io/mission/mission.h"
#include "io/mission/mission_writer.h"
#include "sonar/attitude.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

using test::ScratchDir;

NavTrack sampleTrack() {
  std::vector<NavSample> samples;
  for (int i = 0; i < 20; ++i) {
    const double t = 1000.0 + 0.2 * i;
    samples.push_back({t,
                       {4.0 + 0.01 * i, -2.5 + 0.003 * i, 12.0 + 0.1 * i},
                       quaternionFromRollPitchYaw({0.01 * i, -0.02, degToRad(37) + 0.005 * i})});
  }
  return NavTrack(samples);
}

void expectSameMission(const SonarModel& sonar, const Mounting& mounting, const NavTrack& nav,
                       const std::vector<Frame>& frames, const Mission& read) {
  EXPECT_EQ(read.sonar.id(), sonar.id());
  EXPECT_EQ(read.sonar.rows(), sonar.rows());
  EXPECT_EQ(read.sonar.cols(), sonar.cols());
  EXPECT_EQ(read.sonar.range().min_m, sonar.range().min_m);
  EXPECT_EQ(read.sonar.range().resolution_m, sonar.range().resolution_m);
  EXPECT_EQ(read.sonar.bearings().isUniform(), sonar.bearings().isUniform());
  for (int j = 0; j < sonar.cols(); ++j) {
    // Tables are stored in degrees: equal to far below any beam width (about 1e-3 rad).
    ASSERT_NEAR(read.sonar.bearings().centre(j), sonar.bearings().centre(j), 1e-12) << j;
  }
  EXPECT_EQ(read.sonar.verticalAperture(), sonar.verticalAperture());
  EXPECT_EQ(read.sonar.elevationBeam(), sonar.elevationBeam());
  EXPECT_EQ(read.sonar.intensityScale(), sonar.intensityScale());
  EXPECT_NEAR(read.sonar.horizontalBeamWidth(), sonar.horizontalBeamWidth(), 1e-12);
  EXPECT_TRUE(read.mounting.T_vehicle_sonar().isApprox(mounting.T_vehicle_sonar(), 1e-15));
  ASSERT_EQ(read.nav.samples().size(), nav.samples().size());
  for (std::size_t i = 0; i < nav.samples().size(); ++i) {
    const NavSample& a = nav.samples()[i];
    const NavSample& b = read.nav.samples()[i];
    EXPECT_EQ(a.time_s, b.time_s);
    EXPECT_EQ(a.position_m, b.position_m);
    EXPECT_LT(a.q_world_vehicle.angularDistance(b.q_world_vehicle), 1e-12);
  }
  ASSERT_EQ(read.frames.size(), frames.size());
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const Frame f = loadFrame(read, i);
    EXPECT_EQ(f.time_s, frames[i].time_s);
    EXPECT_EQ(f.sonar_id, sonar.id());
    EXPECT_EQ(cv::norm(f.image, frames[i].image, cv::NORM_INF), 0.0);
  }
}

void roundTrip(const SonarModel& sonar) {
  ScratchDir dir;
  const Mounting mounting{{0.45, -0.1, 0.3}, {0.0, degToRad(-20), degToRad(1.5)}};
  const NavTrack nav = sampleTrack();
  std::vector<Frame> frames;
  MissionWriter writer(dir.path() / "m", "round trip", sonar, mounting);
  cv::RNG rng(5);
  for (int i = 0; i < 4; ++i) {
    Frame f{1000.1 + 0.5 * i, sonar.id(), cv::Mat(sonar.rows(), sonar.cols(), CV_32F)};
    // Whole counts the sonar can hold (rounding below keeps a decibel sonar's at most its full
    // scale), loaded as power as a reader does.
    const IntensityScale& scale = sonar.intensityScale();
    rng.fill(f.image, cv::RNG::UNIFORM, 0, scale.isLinear() ? 65536 : scale.fullScaleCount() + 0.5);
    cv::Mat rounded;
    f.image.convertTo(rounded, CV_16U);
    rounded.convertTo(f.image, CV_32F);
    scale.countsToPower(f.image, "frame");
    writer.addFrame(f);
    frames.push_back(f);
  }
  writer.finish(nav);
  const Mission read = readMission(dir.path() / "m");
  EXPECT_EQ(read.name, "round trip");
  expectSameMission(sonar, mounting, nav, frames, read);
  // The mission can equally be named by its YAML file.
  EXPECT_EQ(readMission(dir.path() / "m" / "mission.yaml").frames.size(), frames.size());
}

TEST(MissionFormat, WriteThenReadGivesTheSameMissionWithUniformBearings) {
  roundTrip(test::paperSonar());
}

TEST(MissionFormat, WriteThenReadGivesTheSameMissionWithABearingTable) {
  roundTrip(test::nonUniformSonar());
}

TEST(MissionFormat, AClippedBeamIsWrittenAndReadBack) {
  // A mission from a clipped-beam simulation says so, and carving stays inside the aperture.
  roundTrip(test::paperSonar().withElevationBeam(ElevationBeam::Clipped));
}

TEST(MissionFormat, ADecibelSonarIsStoredInItsOwnCountsAndReadBackAsTheSamePower) {
  // 80 dB of power do not fit a 16-bit PNG; the sonar's bytes do, and give the power back.
  roundTrip(test::paperSonar().withIntensityScale(IntensityScale::decibel(80.0, 255.0)));
}

TEST(MissionFormat, AGammaSonarIsStoredInItsOwnCountsAndReadBackAsTheSamePower) {
  roundTrip(test::paperSonar().withIntensityScale(IntensityScale::gamma(0.5, 65535.0)));
}

TEST(MissionFormat, ASonarsHorizontalBeamWidthIsKept) {
  // Beams five times as wide as their spacing; a mission that does not say has none (0).
  roundTrip(test::paperSonar().withHorizontalBeamWidth(degToRad(1.0)));
  EXPECT_EQ(readMission(test::exampleMission()).sonar.horizontalBeamWidth(), 0.0);
}

TEST(MissionFormat, TheExampleMissionReadsCompletely) {
  const Mission m = readMission(test::exampleMission());
  EXPECT_EQ(m.frames.size(), 10u);
  EXPECT_EQ(m.sonar.cols(), 64);
  EXPECT_EQ(m.sonar.rows(), 200);
  EXPECT_TRUE(checkFrames(m).empty());
  for (const FrameRecord& f : m.frames) {
    EXPECT_TRUE(m.nav.covers(f.time_s));
  }
}

}  // namespace
}  // namespace sonarcarve
