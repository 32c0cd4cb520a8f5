// Oculus messages and logs: the real ping in tests/data/oculus against the values of its
// README, the other layouts through the test encoder, and every kind of broken input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>

#include "common/angles.h"
#include "common/error.h"
#include "io/frame_source.h"
#include "io/import.h"
#include "io/mission/mission.h"
#include "io/oculus/oculus_log.h"
#include "io/oculus/oculus_message.h"
#include "support/oculus_encoder.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

using test::encodeOculusPing;
using test::expectError;
using test::OculusPingSpec;

TEST(OculusFixture, DecodesTheRealPingAsItsReadmeSays) {
  const OculusLog log = OculusLog::open(test::oculusFixture());
  EXPECT_EQ(log.container(), "oculus messages");
  ASSERT_EQ(log.pings().size(), 1u);
  EXPECT_TRUE(log.problems().empty());
  const OculusPing p = log.decode(0);
  EXPECT_EQ(p.header.msg_id, 35);
  EXPECT_EQ(p.header.msg_version, 0);
  EXPECT_EQ(p.header.payload_size, 182000u);
  EXPECT_EQ(p.master_mode, 2);
  EXPECT_EQ(p.gamma, 127);  // gamma correction 0.5
  EXPECT_EQ(p.flags, 0b11001);
  EXPECT_DOUBLE_EQ(p.range_demand, 2.0);
  EXPECT_DOUBLE_EQ(p.gain_percent, 50.0);
  EXPECT_EQ(p.ping_id, 415323u);
  EXPECT_NEAR(p.frequency_hz, 2098880.6, 0.05);
  EXPECT_NEAR(p.speed_of_sound_mps, 1490.66, 0.005);
  EXPECT_EQ(p.sample_bytes, 1);
  EXPECT_FALSE(p.has_gain);
  EXPECT_DOUBLE_EQ(p.range_resolution_m, 0.0028421889710794315);
  EXPECT_EQ(p.n_ranges, 703);
  EXPECT_EQ(p.n_beams, 256);
  EXPECT_EQ(p.image_offset, 2048u);
  EXPECT_EQ(p.image_size, 179968u);
  ASSERT_EQ(p.bearings_rad.size(), 256u);
  EXPECT_NEAR(radToDeg(p.bearings_rad.front()), -30.0, 1e-9);
  EXPECT_NEAR(radToDeg(p.bearings_rad[1]), -29.74, 1e-9);
  EXPECT_NEAR(radToDeg(p.bearings_rad[127]), -0.11, 1e-9);
  EXPECT_NEAR(radToDeg(p.bearings_rad[128]), 0.11, 1e-9);
  EXPECT_NEAR(radToDeg(p.bearings_rad.back()), 30.0, 1e-9);
  // Not uniform: the beams are 0.26 deg apart at the edges and 0.22 deg at the centre.
  EXPECT_GT(p.bearings_rad[1] - p.bearings_rad[0], p.bearings_rad[128] - p.bearings_rad[127]);
  ASSERT_EQ(p.image.type(), CV_32F);
  ASSERT_EQ(p.image.rows, 703);
  ASSERT_EQ(p.image.cols, 256);
  EXPECT_NEAR(cv::mean(p.image)[0], 55.857, 1e-3);
}

TEST(OculusFixture, SonarModelUsesTheTableAsIs) {
  const OculusLog log = OculusLog::open(test::oculusFixture());
  const OculusImportPlan plan = planOculusImport(log, 0.0, std::nullopt);
  EXPECT_EQ(plan.sonar.cols(), 256);
  EXPECT_EQ(plan.sonar.rows(), 703);
  EXPECT_FALSE(plan.sonar.bearings().isUniform());
  EXPECT_DOUBLE_EQ(plan.sonar.range().resolution_m, 0.0028421889710794315);
  EXPECT_DOUBLE_EQ(plan.sonar.range().min_m, 0.0);
  EXPECT_NEAR(radToDeg(plan.sonar.verticalAperture()), 12.0, 1e-9);  // 2.1 MHz: high frequency
  EXPECT_EQ(plan.sonar.id(), "oculus-2099khz");
  // Its bytes were sent with gamma correction 0.5 (127 of 255), said as a warning.
  EXPECT_EQ(plan.sonar.intensityScale(), IntensityScale::gamma(0.498, 255.0));
  EXPECT_TRUE(std::any_of(plan.warnings.begin(), plan.warnings.end(), [](const std::string& w) {
    return w.find("gamma 0.498 (255 counts full scale) (the fire message's gammaCorrection 127)") !=
           std::string::npos;
  }));
  ASSERT_EQ(plan.frame_times_s.size(), 1u);
  // Version 0 ping time: pingStartTime 3103899264 read as microseconds.
  EXPECT_NEAR(plan.frame_times_s[0], 3103.899264, 1e-9);
  EXPECT_NEAR(planOculusImport(log, 2.5, 20.0).frame_times_s[0], 3106.399264, 1e-9);
  EXPECT_NEAR(radToDeg(planOculusImport(log, 0, 20.0).sonar.verticalAperture()), 20.0, 1e-9);
}

TEST(OculusFixture, LooksLikeAnOculusLog) {
  EXPECT_TRUE(looksLikeOculusLog(test::oculusFixture()));
  EXPECT_FALSE(looksLikeOculusLog(test::exampleMission()));
  EXPECT_FALSE(looksLikeOculusLog(test::exampleMission() / "mission.yaml"));
  EXPECT_FALSE(looksLikeOculusLog("/nonexistent/file.raw"));
}

// The decoder's fixed sizes are those of the packed structures of the public Oculus.h
// (sizeof(OculusSimplePingResult) = 122, sizeof(OculusSimplePingResult2) = 202); the encoder
// lays the fields out one by one and checks the same sizes.
TEST(OculusMessages, LayoutSizesMatchThePublicHeader) {
  EXPECT_EQ(kOculusPingV1Size, 122u);
  EXPECT_EQ(kOculusPingV2Size, 202u);
  for (std::uint16_t version : {0, 1, 2}) {
    OculusPingSpec spec;
    spec.version = version;
    EXPECT_NO_THROW(encodeOculusPing(spec));
  }
}

struct LayoutCase {
  std::uint16_t version;
  bool sixteen_bit;
  bool gain;
};

class OculusLayouts : public ::testing::TestWithParam<LayoutCase> {};

TEST_P(OculusLayouts, RoundTripThroughTheEncoder) {
  OculusPingSpec spec;
  spec.version = GetParam().version;
  spec.sixteen_bit = GetParam().sixteen_bit;
  spec.gain = GetParam().gain;
  spec.n_beams = 24;
  spec.n_ranges = 13;
  spec.range_resolution_m = 0.0125;
  spec.frequency_hz = 1.2e6;
  spec.speed_of_sound_mps = 1502.5;
  spec.ping_id = 77;
  spec.ping_start_time = 1234.5;
  spec.heading_deg = 90.5;
  spec.pitch_deg = -2.0;
  spec.roll_deg = 1.5;
  const auto bytes = encodeOculusPing(spec);
  const OculusPing p = decodeOculusPing(bytes, 0, "mem");
  EXPECT_EQ(p.header.msg_version, spec.version);
  EXPECT_EQ(p.n_beams, 24);
  EXPECT_EQ(p.n_ranges, 13);
  EXPECT_EQ(p.sample_bytes, spec.sixteen_bit ? 2 : 1);
  EXPECT_EQ(p.has_gain, spec.gain);
  EXPECT_DOUBLE_EQ(p.range_resolution_m, 0.0125);
  EXPECT_DOUBLE_EQ(p.frequency_hz, 1.2e6);
  EXPECT_DOUBLE_EQ(p.speed_of_sound_mps, 1502.5);
  EXPECT_EQ(p.ping_id, 77u);
  EXPECT_DOUBLE_EQ(p.temperature_c, 12.5);
  EXPECT_DOUBLE_EQ(p.pressure_bar, 3.25);
  if (spec.version == 2) {
    EXPECT_DOUBLE_EQ(p.ping_start_time, 1234.5);
    EXPECT_DOUBLE_EQ(p.heading_deg, 90.5);
    EXPECT_DOUBLE_EQ(p.pitch_deg, -2.0);
    EXPECT_DOUBLE_EQ(p.roll_deg, 1.5);
  } else {
    EXPECT_DOUBLE_EQ(p.ping_start_time, 1234.0);  // a u32 in this layout
    EXPECT_DOUBLE_EQ(p.heading_deg, 0.0);
  }
  const auto table = test::oculusBearings(24);
  for (int j = 0; j < 24; ++j) {
    EXPECT_NEAR(radToDeg(p.bearings_rad[j]), table[j] * 0.01, 1e-12);
  }
  ASSERT_EQ(p.image.rows, 13);
  for (int r = 0; r < 13; ++r) {
    for (int c = 0; c < 24; ++c) {
      ASSERT_EQ(p.image.at<float>(r, c), test::oculusSample(spec, r, c)) << r << "," << c;
    }
    if (spec.gain) {
      EXPECT_EQ(p.row_gain[r], test::oculusRowGain(r));
    }
  }
  EXPECT_EQ(p.row_gain.empty(), !spec.gain);
  if (spec.sixteen_bit) {
    double max = 0;
    cv::minMaxLoc(p.image, nullptr, &max);
    EXPECT_GT(max, 255.0);  // 16-bit values kept as they are
  }
}

INSTANTIATE_TEST_SUITE_P(AllLayouts, OculusLayouts,
                         ::testing::Values(LayoutCase{0, false, false}, LayoutCase{1, false, true},
                                           LayoutCase{1, true, false}, LayoutCase{2, false, false},
                                           LayoutCase{2, true, false}, LayoutCase{2, true, true},
                                           LayoutCase{2, false, true}),
                         [](const auto& param_info) {
                           const LayoutCase& c = param_info.param;
                           return "v" + std::to_string(c.version) +
                                  (c.sixteen_bit ? "_16bit" : "_8bit") + (c.gain ? "_gain" : "");
                         });

TEST(OculusLogs, ManyMessagesBackToBackWithStatusMessagesSkipped) {
  std::vector<std::vector<std::uint8_t>> parts;
  for (int i = 0; i < 5; ++i) {
    OculusPingSpec spec;
    spec.version = 2;
    spec.ping_id = 100 + i;
    spec.ping_start_time = 10.0 + 0.1 * i;
    parts.push_back(encodeOculusPing(spec));
    parts.push_back(test::encodeOculusMessage(0x80, 0, std::vector<std::uint8_t>(37, 1)));
  }
  parts.push_back(test::encodeOculusMessage(0xff, 0, {}));
  const OculusLog log = OculusLog::fromBytes(test::concat(parts), "five.raw");
  ASSERT_EQ(log.pings().size(), 5u);
  EXPECT_TRUE(log.problems().empty());
  ASSERT_EQ(log.notes().size(), 2u);
  EXPECT_NE(log.notes()[0].find("5 x message id 128 (logs) skipped"), std::string::npos)
      << log.notes()[0];
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(log.pings()[i].ping.ping_id, 100u + i);
    EXPECT_DOUBLE_EQ(log.pings()[i].time_s, 10.0 + 0.1 * i);
    EXPECT_EQ(log.decode(i).image.rows, 10);
  }
}

TEST(OculusLogs, VersionOneTimesAreMicrosecondsAndUnwrapped) {
  std::vector<std::vector<std::uint8_t>> parts;
  for (double raw : {4294000000.0, 4294900000.0, 1000.0}) {
    OculusPingSpec spec;
    spec.ping_start_time = raw;
    parts.push_back(encodeOculusPing(spec));
  }
  const OculusLog log = OculusLog::fromBytes(test::concat(parts), "wrap.raw");
  ASSERT_EQ(log.pings().size(), 3u);
  EXPECT_NEAR(log.pings()[0].time_s, 4294.0, 1e-9);
  EXPECT_NEAR(log.pings()[1].time_s, 4294.9, 1e-9);
  EXPECT_NEAR(log.pings()[2].time_s, (4294967296.0 + 1000.0) * 1e-6, 1e-9);
}

TEST(OculusLogs, ACorruptMessageInTheMiddleIsSkippedAndReported) {
  OculusPingSpec spec;
  const auto good = encodeOculusPing(spec);
  auto bad = good;
  bad[110] = 0x01;  // imageOffset (v1 layout) now inside the bearing table
  bad[111] = 0x00;
  const auto bytes = test::concat({good, bad, good});
  const OculusLog log = OculusLog::fromBytes(bytes, "middle.raw");
  EXPECT_EQ(log.pings().size(), 2u);
  ASSERT_EQ(log.problems().size(), 1u);
  EXPECT_NE(log.problems()[0].find("middle.raw: byte " + std::to_string(good.size() + 110)),
            std::string::npos)
      << log.problems()[0];
  EXPECT_NE(log.problems()[0].find("imageOffset"), std::string::npos);
}

TEST(OculusLogs, GarbageBetweenMessagesIsSkippedToTheNextMessage) {
  const auto good = encodeOculusPing({});
  const auto bytes = test::concat({good, std::vector<std::uint8_t>(100, 0xab), good});
  const OculusLog log = OculusLog::fromBytes(bytes, "garbage.raw");
  EXPECT_EQ(log.pings().size(), 2u);
  ASSERT_EQ(log.problems().size(), 1u);
  EXPECT_NE(log.problems()[0].find("byte " + std::to_string(good.size()) +
                                   ": 100 bytes that are not an Oculus message"),
            std::string::npos)
      << log.problems()[0];
}

TEST(OculusLogs, ATruncatedLastMessageIsReportedAndTheRestKept) {
  const auto good = encodeOculusPing({});
  auto bytes = test::concat({good, good});
  bytes.resize(bytes.size() - 7);
  const OculusLog log = OculusLog::fromBytes(bytes, "cut.raw");
  EXPECT_EQ(log.pings().size(), 1u);
  ASSERT_EQ(log.problems().size(), 1u);
  EXPECT_NE(log.problems()[0].find("cut.raw: byte " + std::to_string(good.size() + 10)),
            std::string::npos)
      << log.problems()[0];
  EXPECT_NE(log.problems()[0].find("cut off"), std::string::npos);
}

TEST(OculusErrors, TheFixtureCutAtManyOffsetsNamesFileAndByte) {
  const auto whole = test::readBytes(test::oculusFixture().string());
  for (std::size_t size : {1ul, 2ul, 15ul, 16ul, 17ul, 60ul, 121ul, 122ul, 500ul, 2048ul, 100000ul,
                           whole.size() - 1}) {
    const std::vector<std::uint8_t> cut(whole.begin(), whole.begin() + size);
    expectError([&] { OculusLog::fromBytes(cut, "cut.raw"); }, {"cut.raw", "byte "});
    expectError([&] { decodeOculusPing(cut, 0, "cut.raw"); }, {"cut.raw: byte "});
  }
}

TEST(OculusErrors, EmptyUnrecognisedAndWrongMagic) {
  expectError([] { OculusLog::fromBytes({}, "empty.raw"); }, {"empty.raw: byte 0: empty file"});
  expectError(
      [] {
        OculusLog::fromBytes({'h', 'e', 'l', 'l', 'o'}, "text.raw");
      },
      {"text.raw: byte 0: not an Oculus log"});
  auto bytes = encodeOculusPing({});
  bytes[0] = 0x00;
  expectError([&] { decodeOculusPing(bytes, 0, "m"); },
              {"m: byte 0: not an Oculus message: oculusId is 0x4f00"});
  expectError([] { OculusLog::open("/nonexistent/log.raw"); },
              {"/nonexistent/log.raw: not found: expected an Oculus log"});
  std::vector<std::uint8_t> sqlite = {'S', 'Q', 'L', 'i', 't', 'e', ' ', 'f',
                                      'o', 'r', 'm', 'a', 't', ' ', '3', 0};
  expectError([&] { OculusLog::fromBytes(sqlite, "v2.oculus"); }, {"v2.oculus: byte 0", "SQLite"});
}

TEST(OculusErrors, CorruptFieldsNameTheByte) {
  const auto good = encodeOculusPing({});  // version 0 layout
  const auto corrupt = [&](std::size_t at, std::vector<std::uint8_t> value) {
    auto bytes = good;
    std::copy(value.begin(), value.end(), bytes.begin() + static_cast<long>(at));
    return bytes;
  };
  struct Case {
    std::size_t at;
    std::vector<std::uint8_t> value;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {6, {0x22, 0}, "byte 6: message id 34 is not a simple ping result"},
      {8, {3, 0}, "byte 8: unknown simple ping result version 3"},
      {10, {0xff, 0xff, 0xff, 0x0f}, "byte 10: truncated message: payloadSize"},
      {10, {50, 0, 0, 0}, "byte 10: payloadSize 50 is too small"},
      {97, {2}, "byte 97: dataSize 2"},
      {98, {0, 0, 0, 0, 0, 0, 0, 0}, "byte 98: rangeResolution: expected 1e-04 to 10 m, got 0"},
      {98,
       {0, 0, 0, 0, 0, 0, 0xf8, 0x7f},
       "byte 98: rangeResolution: expected 1e-04 to 10 m, got nan"},
      {106, {0, 0}, "byte 106: nRanges is 0"},
      {108, {0, 0}, "byte 108: nBeams 0"},
      {108, {0xff, 0xff}, "byte 108: nBeams 65535"},
      {108, {0, 1}, "byte 122: truncated bearing table"},
      {114, {1, 2, 3, 0}, "byte 114: imageSize 197121 does not match"},
      {110, {0xff, 0xff, 0, 0}, "byte 110: image (imageOffset 65535"},
      {110, {10, 0, 0, 0}, "byte 110: imageOffset 10 overlaps"},
      {124, {0x00, 0x80}, "byte 124: bearing 1 is -327.68 deg"},
      {124, {0x00, 0xe0}, "byte 124: bearing table does not increase"},
  };
  for (const Case& c : cases) {
    expectError([&] { decodeOculusPing(corrupt(c.at, c.value), 0, "f.raw"); },
                {"f.raw: " + c.expected});
  }
}

TEST(OculusRecordings, ItemsPlainAndCompressedWithTheirTimes) {
  OculusPingSpec a;
  a.ping_id = 1;
  OculusPingSpec b;
  b.version = 2;
  b.sixteen_bit = true;
  b.gain = true;
  b.ping_id = 2;
  const auto bytes = test::encodeRecording({
      {1, 99.0, std::vector<std::uint8_t>(20, 7), false},  // settings: skipped
      {10, 1700000001.25, encodeOculusPing(a), false},
      {10, 1700000001.5, encodeOculusPing(b), true},
  });
  const OculusLog log = OculusLog::fromBytes(bytes, "rec.oculus");
  EXPECT_EQ(log.container(), "oculus viewpoint recording v1");
  EXPECT_TRUE(log.problems().empty()) << log.problems().front();
  ASSERT_EQ(log.pings().size(), 2u);
  EXPECT_DOUBLE_EQ(log.pings()[0].time_s, 1700000001.25);
  EXPECT_DOUBLE_EQ(log.pings()[1].time_s, 1700000001.5);
  ASSERT_EQ(log.notes().size(), 1u);
  EXPECT_NE(log.notes()[0].find("1 x item type 1 (settings) skipped"), std::string::npos);
  const OculusPing pb = log.decode(1);
  EXPECT_EQ(pb.ping_id, 2u);
  EXPECT_EQ(pb.image.at<float>(3, 5), test::oculusSample(b, 3, 5));
  EXPECT_EQ(pb.row_gain[4], test::oculusRowGain(4));
  EXPECT_EQ(log.decode(0).image.at<float>(9, 15), test::oculusSample(a, 9, 15));
}

TEST(OculusRecordings, BrokenRecordingsNameTheByte) {
  const auto ping = encodeOculusPing({});
  auto bytes = test::encodeRecording({{10, 1.0, ping, false}, {10, 2.0, ping, false}});
  // The second item cut off: the first ping kept, the cut reported.
  auto cut = bytes;
  cut.resize(cut.size() - 5);
  const OculusLog log = OculusLog::fromBytes(cut, "cut.oculus");
  EXPECT_EQ(log.pings().size(), 1u);
  ASSERT_EQ(log.problems().size(), 1u);
  EXPECT_NE(log.problems()[0].find("byte " + std::to_string(48 + 40 + ping.size() + 32)),
            std::string::npos)
      << log.problems()[0];
  // Encrypted, header cut, corrupt compressed item.
  auto encrypted = bytes;
  encrypted[26] = 1;
  expectError([&] { OculusLog::fromBytes(encrypted, "enc.oculus"); },
              {"enc.oculus: byte 26: encrypted"});
  const std::vector<std::uint8_t> header_only(bytes.begin(), bytes.begin() + 30);
  expectError([&] { OculusLog::fromBytes(header_only, "h.oculus"); },
              {"h.oculus: byte 30: truncated Oculus ViewPoint file header"});
  auto compressed = test::encodeRecording({{10, 1.0, ping, true}});
  compressed[48 + 40 + 10] ^= 0xff;
  expectError([&] { OculusLog::fromBytes(compressed, "z.oculus"); },
              {"z.oculus", "byte 92", "corrupt compressed item"});
}

TEST(OculusImport, PingsLoadOnTheSonarsLinearScaleAndAnotherGammaIsLeftOut) {
  test::ScratchDir dir;
  std::vector<std::vector<std::uint8_t>> parts;
  for (int i = 0; i < 3; ++i) {
    OculusPingSpec spec;
    spec.sixteen_bit = true;
    spec.ping_start_time = 1e6 * i;
    spec.gamma = i == 2 ? 255 : 127;  // the last ping linear
    parts.push_back(encodeOculusPing(spec));
  }
  const auto log = dir.path() / "g.bin";
  test::writeBytes(log.string(), test::concat(parts));
  const OculusLog read = OculusLog::open(log);
  const OculusImportPlan plan = planOculusImport(read, 0.0, std::nullopt);
  EXPECT_EQ(plan.sonar.intensityScale(), IntensityScale::gamma(0.498, 65535.0));
  EXPECT_EQ(plan.pings, (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(oculusIntensityScale(read.decode(2)), IntensityScale::linear());
  // In place and imported, a frame loads as 65535 (count / 65535)^(1 / 0.498).
  ImportRequest request;
  request.log = log;
  request.out = dir.path() / "mission";
  SilentProgress progress;
  EXPECT_EQ(importOculusToMission(request, progress).frames_written, 2u);
  OculusPingSpec spec;
  spec.sixteen_bit = true;
  for (const Mission& mission : {openMission(log), readMission(request.out)}) {
    const Frame frame = loadFrame(mission, 1);
    for (const auto& [row, col] : {std::pair{0, 0}, std::pair{4, 7}, std::pair{9, 15}}) {
      const double count = oculusSample(spec, row, col);
      // Float arithmetic: a few float epsilons, times the exponent for the power.
      const double expected = 65535.0 * std::pow(count / 65535.0, 1 / 0.498);
      EXPECT_NEAR(frame.image.at<float>(row, col), expected, 1e-5 * expected)
          << mission.folder << " " << row << "," << col;
    }
  }
}

TEST(OculusImport, KeepsTheMainGeometryAndStopsWhenCancelled) {
  test::ScratchDir dir;
  std::vector<std::vector<std::uint8_t>> parts;
  for (int i = 0; i < 4; ++i) {
    OculusPingSpec spec;
    spec.version = 2;
    spec.ping_start_time = 20.0 - i;  // backwards: sorted on import
    spec.n_beams = i == 1 ? 8 : 16;   // one ping after a range change
    parts.push_back(encodeOculusPing(spec));
  }
  const auto log = dir.path() / "mixed.raw";
  test::writeBytes(log.string(), test::concat(parts));
  ImportRequest request;
  request.log = log;
  request.out = dir.path() / "mission";
  SilentProgress progress;
  const ImportReport report = importOculusToMission(request, progress);
  EXPECT_EQ(report.pings_in_log, 4u);
  EXPECT_EQ(report.frames_written, 3u);
  const auto has = [&](const std::string& text) {
    return std::any_of(report.warnings.begin(), report.warnings.end(),
                       [&](const std::string& w) { return w.find(text) != std::string::npos; });
  };
  EXPECT_TRUE(has("1 of 4 pings have another range window, bearing table or sample scale"));
  EXPECT_TRUE(has("sorted by time"));
  EXPECT_TRUE(has("stationary"));
  const Mission mission = readMission(request.out);
  ASSERT_EQ(mission.frames.size(), 3u);
  EXPECT_DOUBLE_EQ(mission.frames[0].time_s, 17.0);
  EXPECT_DOUBLE_EQ(mission.frames[2].time_s, 20.0);
  EXPECT_EQ(mission.sonar.cols(), 16);

  request.out = dir.path() / "cancelled";
  progress.cancel();
  EXPECT_THROW(importOculusToMission(request, progress), Cancelled);
  EXPECT_FALSE(std::filesystem::exists(request.out / "mission.yaml"));
  // An existing mission is never overwritten.
  request.out = dir.path() / "mission";
  expectError([&] { importOculusToMission(request, *std::make_unique<SilentProgress>()); },
              {"mission", "output folder exists and is not empty"});
}

}  // namespace
}  // namespace sonarcarve
