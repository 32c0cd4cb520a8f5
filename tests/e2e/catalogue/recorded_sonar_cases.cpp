// Class "sonars read from recordings" (issue 44): an Oculus log, an ARIS recording and a ROS 2
// bag declare their sonar's geometry in every ping, frame header or message. Each is held to
// the ranges of a mission.yaml's sonar keys (sonar/sonar_ranges.h): a range resolution of
// 1e-300, a window that starts 3000 km away, a field of view or an aperture of nothing, a NaN
// sound speed. A bad ping among good ones is skipped and reported; a recording whose first
// frame is bad is refused; each message names the file, the frame (or byte) and the field.
#include <cmath>
#include <cstring>
#include <limits>

#include "e2e/catalogue/catalogue.h"
#include "io/mission/mission.h"
#include "io/rosbag/bag_writer.h"
#include "sonar/sonar_model.h"

namespace sonarcarve::test {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// tests/data/oculus/one_ping_8bit.raw: a version 0 ping of 182,016 bytes.
constexpr std::size_t kPingBytes = 182016;
constexpr std::size_t kSpeedOfSoundUsedAt = 85, kRangeResolutionAt = 98;

// Three copies of the real ping, `field` of the second set to `value`: the second is skipped,
// `info` lists the other two and the problem.
CatalogueCase oculusPing(const std::string& name, std::size_t field, double value,
                         const std::string& message) {
  return {.name = name,
          .prepare =
              [field, value](const Workspace& ws) {
                const std::string ping = readText(testData("oculus/one_ping_8bit.raw"));
                std::string log = ping + ping + ping;
                std::memcpy(log.data() + kPingBytes + field, &value, sizeof value);
                writeBytes(ws / "log.raw", log);
                return std::string("info log.raw");
              },
          .outcome = Outcome::Succeeds,
          .message = {"log.raw: byte " + std::to_string(kPingBytes + field) + ": " + message,
                      "(message at byte " + std::to_string(kPingBytes) + " skipped)"}};
}

// tests/data/aris/sample.aris: a 1024-byte file header, then frames of a 1024-byte header and
// 48 beams x 2000 samples.
constexpr std::size_t kArisFrameBytes = 1024 + 48 * 2000;
constexpr std::size_t kSamplePeriodAt = 452, kSoundSpeedAt = 464, kSampleStartDelayAt = 476;

template <typename T>
CatalogueCase arisFrame(const std::string& name, int frame,
                        std::vector<std::pair<std::size_t, T>> fields, const std::string& message) {
  return {.name = name,
          .prepare =
              [frame, fields](const Workspace& ws) {
                std::string bytes = readText(testData("aris/sample.aris"));
                for (const auto& [at, value] : fields) {
                  std::memcpy(bytes.data() + 1024 + frame * kArisFrameBytes + at, &value,
                              sizeof value);
                }
                writeBytes(ws / "bad.aris", bytes);
                return std::string("info bad.aris");
              },
          // Frame 0 sets the recording's geometry: refused. A later frame stops the reading
          // there, reported.
          .outcome = frame == 0 ? Outcome::Fails : Outcome::Succeeds,
          .message = {"bad.aris: frame " + std::to_string(frame) + ", byte " +
                      std::to_string(1024 + frame * kArisFrameBytes) + ": " + message}};
}

// The example mission written as a ROS 2 bag whose sonar declares another geometry (the same
// beams and bins, so the frames fit), then reconstructed: every message is refused.
CatalogueCase bagGeometry(const std::string& name, double near_m, double resolution_m,
                          double bearing_step_rad, double aperture_rad,
                          const std::string& message) {
  return {.name = name,
          .prepare =
              [=](const Workspace& ws) {
                Mission mission = readMission(ws.mission());
                const SonarModel& s = mission.sonar;
                std::vector<double> centres;
                for (int b = 0; b < s.cols(); ++b) {
                  centres.push_back(bearing_step_rad * (b - s.cols() / 2));
                }
                mission.sonar = SonarModel(s.id(), RangeBins{near_m, resolution_m, s.rows()},
                                           BearingTable::fromCentres(centres), aperture_rad);
                BagWriteOptions options;
                options.format = BagFormat::McapNone;
                writeRosBag(mission, ws / "bad.mcap", options);
                return std::string("reconstruct bad.mcap --out out");
              },
          .message = {"bad.mcap", message},
          .absent = {"out"}};
}

// Where each sonar message of a bag written from the example mission holds its
// ping_info.tx_beamwidths: the sequence's length (one width a beam) and the widths, all the
// mission's aperture. Its sound_speed is the float before.
std::vector<std::size_t> txBeamwidthsAt(const std::string& bag, const SonarModel& sonar) {
  std::string pattern(4, '\0');
  const auto beams = static_cast<std::uint32_t>(sonar.cols());
  std::memcpy(pattern.data(), &beams, 4);
  const auto aperture = static_cast<float>(sonar.verticalAperture());
  for (std::uint32_t b = 0; b < beams; ++b) {
    pattern.append(reinterpret_cast<const char*>(&aperture), 4);
  }
  std::vector<std::size_t> found;
  for (auto at = bag.find(pattern); at != std::string::npos; at = bag.find(pattern, at + 1)) {
    found.push_back(at);
  }
  return found;
}

// The example mission as an MCAP bag (messages in the data section: no chunk CRC to keep),
// each sonar message's ping_info changed by `change` (its bytes, where its tx_beamwidths start,
// the message's index), read by `info`.
CatalogueCase bagPingInfo(const std::string& name,
                          std::function<void(std::string&, std::size_t, std::size_t)> change,
                          const std::vector<std::string>& message) {
  return {.name = name,
          .prepare =
              [change](const Workspace& ws) {
                const Mission mission = readMission(ws.mission());
                BagWriteOptions options;
                options.format = BagFormat::McapUnchunked;
                writeRosBag(mission, ws / "bag.mcap", options);
                std::string bytes = readText(ws / "bag.mcap");
                const std::vector<std::size_t> at = txBeamwidthsAt(bytes, mission.sonar);
                EXPECT_EQ(at.size(), mission.frames.size());
                for (std::size_t i = 0; i < at.size(); ++i) {
                  change(bytes, at[i], i);
                }
                writeBytes(ws / "bag.mcap", bytes);
                return std::string("info bag.mcap");
              },
          .outcome = Outcome::Succeeds,
          .message = message};
}

void setFloat(std::string& bytes, std::size_t at, float value) {
  std::memcpy(bytes.data() + at, &value, sizeof value);
}

}  // namespace

std::vector<CatalogueCase> recordedSonarCases() {
  const double step = 0.01;  // rad between beams: the example's 64 beams span 36 degrees
  return {
      oculusPing("OculusRangeResolutionTiny", kRangeResolutionAt, 1e-300,
                 "rangeResolution: expected 1e-04 to 10 m, got 1e-300"),
      oculusPing("OculusRangeResolutionHuge", kRangeResolutionAt, 1e300,
                 "rangeResolution: expected 1e-04 to 10 m, got 1e+300"),
      oculusPing("OculusRangeResolutionNegative", kRangeResolutionAt, -0.003,
                 "rangeResolution: expected 1e-04 to 10 m, got -0.003"),
      oculusPing("OculusRangeResolutionNaN", kRangeResolutionAt, kNaN,
                 "rangeResolution: expected 1e-04 to 10 m, got nan"),
      oculusPing("OculusSoundSpeedNaN", kSpeedOfSoundUsedAt, kNaN,
                 "speedOfSoundUsed: expected 1000 to 2000 m/s, got nan"),
      oculusPing("OculusSoundSpeedZero", kSpeedOfSoundUsedAt, 0.0,
                 "speedOfSoundUsed: expected 1000 to 2000 m/s, got 0"),
      oculusPing("OculusSoundSpeedHuge", kSpeedOfSoundUsedAt, 1e300,
                 "speedOfSoundUsed: expected 1000 to 2000 m/s, got 1e+300"),
      arisFrame<float>("ArisSoundSpeedNaN", 0, {{kSoundSpeedAt, std::nanf("")}},
                       "SoundSpeed: expected 1000 to 2000 m/s, got nan"),
      arisFrame<float>(
          "ArisSoundSpeedHugeInALaterFrame", 2, {{kSoundSpeedAt, 1e30F}},
          "SoundSpeed: expected 1000 to 2000 m/s, got 1.0000000150474662e+30; reading stopped"),
      arisFrame<std::uint32_t>("ArisSamplePeriodHuge", 0, {{kSamplePeriodAt, 4000000000U}},
                               "SamplePeriod (a sample's length): expected 1e-04 to 10 m, got"),
      arisFrame<std::uint32_t>("ArisWindowStartHuge", 0, {{kSampleStartDelayAt, 4000000000U}},
                               "SampleStartDelay (the window's start): expected 0 to 1000 m, got"),
      // 900 m away, 2000 samples of 5 m: the window ends 10.9 km away.
      arisFrame<std::uint32_t>("ArisWindowFarther10Km", 0,
                               {{kSampleStartDelayAt, 1200000U}, {kSamplePeriodAt, 6667U}},
                               "SamplePeriod (a sample's length): the farthest range is"),
      bagGeometry("BagRangeResolutionTiny", 0.0, 1e-30, step, 0.2,
                  "ranges (their spacing): expected 1e-04 to 10 m, got"),
      bagGeometry("BagNearRangeHuge", 5000.0, 0.01, step, 0.2,
                  "ranges (the first): expected 0 to 1000 m, got"),
      bagGeometry("BagRangeResolutionHuge", 0.0, 20.0, step, 0.2,
                  "ranges (their spacing): expected 1e-04 to 10 m, got 20"),
      bagGeometry("BagFieldOfViewOfNothing", 0.0, 0.01, 1e-9, 0.2,
                  "beam_directions (their span of bearings): expected 0.1 to 360 (excluded) "
                  "degrees, got"),
      bagGeometry("BagApertureOfNothing", 0.0, 0.01, step, 1e-30,
                  "ping_info.tx_beamwidths: expected 0.1 to 180 (excluded) degrees, got"),
      // The sound speed changes from message to message within the sea's: every frame is read
      // (ranges are in metres, the sound speed is not used).
      bagPingInfo("BagSoundSpeedChangingWithinItsRange",
                  [](std::string& bytes, std::size_t at, std::size_t i) {
                    setFloat(bytes, at - 4, 1500.0F - 10.0F * static_cast<float>(i));
                  },
                  {"Frames       10,"}),
      // A later message out of any sea, or whose aperture is nothing, is skipped and reported.
      bagPingInfo("BagSoundSpeedHugeInALaterMessage",
                  [](std::string& bytes, std::size_t at, std::size_t i) {
                    setFloat(bytes, at - 4, i == 3 ? 1e30F : 1500.0F);
                  },
                  {"Frames       9,", "bag.mcap: message ",
                   "sound_speed: expected 1000 to 2000 m/s, got 1.0000000150474662e+30 (or 0 "
                   "when not known) (message skipped)"}),
      bagPingInfo("BagApertureOfNothingInALaterMessage",
                  [](std::string& bytes, std::size_t at, std::size_t i) {
                    for (std::size_t b = 0; i == 3 && b < 64; ++b) {
                      setFloat(bytes, at + 4 + 4 * b, 1e-30F);
                    }
                  },
                  {"Frames       9,", "bag.mcap: message ",
                   "ping_info.tx_beamwidths: expected 0.1 to 180 (excluded) degrees, got "
                   "5.729577969477164e-29 (message skipped)"}),
  };
}

}  // namespace sonarcarve::test
