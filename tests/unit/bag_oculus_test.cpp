// Oculus pings carried raw in ROS 2 bags: the real ping of tests/data/oculus wrapped in a
// driver's raw data message (apl_msgs/msg/RawData: a std_msgs/Header, a direction byte and the
// bytes) and in a std_msgs/msg/UInt8MultiArray (no header), written by our bag writer as MCAP
// and .db3, must come back as the frame the Oculus reader makes of the same bytes; a cut ping
// is skipped and reported by bag, topic and message, the others read.
#include <gtest/gtest.h>

#include "io/frame_source.h"
#include "io/import.h"
#include "io/oculus/oculus_log.h"
#include "io/rosbag/bag_oculus.h"
#include "io/rosbag/bag_writer.h"
#include "io/rosbag/cdr.h"
#include "support/oculus_encoder.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

constexpr const char* kRawDataDefinition =
    "# raw bytes to and from a device\n"
    "std_msgs/Header header\n"
    "uint8 DATA_OUT=0\n"
    "uint8 DATA_IN=1\n"
    "uint8 direction\n"
    "uint8[] data\n"
    "================================================================================\n"
    "MSG: std_msgs/Header\n"
    "builtin_interfaces/Time stamp\n"
    "string frame_id\n";

constexpr const char* kMultiArrayDefinition =
    "std_msgs/MultiArrayLayout layout\n"
    "uint8[] data\n";

// apl_msgs/msg/RawData as CDR.
std::vector<std::uint8_t> rawDataMessage(std::int64_t stamp_ns, std::uint8_t direction,
                                         const std::vector<std::uint8_t>& bytes) {
  CdrWriter out;
  out.write(static_cast<std::int32_t>(stamp_ns / 1000000000));
  out.write(static_cast<std::uint32_t>(stamp_ns % 1000000000));
  out.writeString("oculus");
  out.write(direction);
  out.writeCount(bytes.size());
  out.writeBytes(bytes);
  return out.bytes();
}

// std_msgs/msg/UInt8MultiArray with one labelled dimension, as CDR.
std::vector<std::uint8_t> multiArrayMessage(const std::vector<std::uint8_t>& bytes) {
  CdrWriter out;
  out.writeCount(1);
  out.writeString("ping");
  out.write(static_cast<std::uint32_t>(bytes.size()));
  out.write(static_cast<std::uint32_t>(1));
  out.write(static_cast<std::uint32_t>(0));  // data_offset
  out.writeCount(bytes.size());
  out.writeBytes(bytes);
  return out.bytes();
}

struct RawBag {
  std::filesystem::path path;
  std::vector<std::int64_t> stamps_ns;   ///< of the pings, in order
  std::vector<std::int64_t> receive_ns;  ///< of the pings
};

constexpr std::int64_t kReceiveDelayNs = 40'000'000;

// Three copies of the real ping 0.2 s apart on /oculus/raw_data, with a fire command sent to
// the sonar before them and a stray byte between them, as liboculus' raw data stream holds.
RawBag writeRawDataBag(const test::ScratchDir& dir, BagFormat format, const std::string& name,
                       const std::vector<std::uint8_t>& ping, bool cut_second = false) {
  RawBag bag{dir.path() / name, {}, {}};
  std::vector<BagMessageSpec> messages;
  const std::vector<std::uint8_t> fire =
      test::encodeOculusMessage(0x15, 1, std::vector<std::uint8_t>(40, 0));
  messages.push_back({0, 1'000'000'000, rawDataMessage(1'000'000'000, 0, fire)});
  for (int k = 0; k < 3; ++k) {
    const std::int64_t stamp = 10'000'000'000 + k * 200'000'000LL;
    std::vector<std::uint8_t> bytes = ping;
    if (cut_second && k == 1) {
      bytes.resize(1000);  // the header still says 182,000 bytes of payload
    }
    messages.push_back({0, stamp + kReceiveDelayNs, rawDataMessage(stamp, 1, bytes)});
    if (!(cut_second && k == 1)) {
      bag.stamps_ns.push_back(stamp);
      bag.receive_ns.push_back(stamp + kReceiveDelayNs);
    }
    messages.push_back({0, stamp + kReceiveDelayNs + 1, rawDataMessage(stamp, 1, {0x42})});
  }
  writeBagMessages(bag.path, format,
                   {{"/oculus/raw_data", "apl_msgs/msg/RawData", kRawDataDefinition}}, messages);
  return bag;
}

bool anyContains(const std::vector<std::string>& lines, const std::vector<std::string>& parts) {
  for (const std::string& line : lines) {
    bool all = true;
    for (const std::string& part : parts) {
      all = all && line.find(part) != std::string::npos;
    }
    if (all) {
      return true;
    }
  }
  return false;
}

// What the Oculus reader makes of the same bytes: the sonar model and the image.
struct OculusReference {
  SonarModel sonar;
  cv::Mat image;
};
OculusReference oculusReference(const std::vector<std::uint8_t>& ping) {
  const OculusLog log = OculusLog::fromBytes(ping, "fixture");
  const OculusImportPlan plan = planOculusImport(log, 0.0, std::nullopt);
  cv::Mat power = log.decode(plan.pings.front()).image;  // counts as sent, then as loaded
  plan.sonar.intensityScale().countsToPower(power, "fixture");
  return {plan.sonar, power};
}

void expectSameFrames(const Mission& read, const OculusReference& reference,
                      const std::vector<std::int64_t>& times_ns) {
  // The same sonar: 256 beams x 703 ranges of 2.84 mm from 0 m, the sonar's own bearings.
  ASSERT_EQ(read.sonar.cols(), reference.sonar.cols());
  ASSERT_EQ(read.sonar.rows(), reference.sonar.rows());
  EXPECT_EQ(read.sonar.cols(), 256);
  EXPECT_EQ(read.sonar.rows(), 703);
  EXPECT_DOUBLE_EQ(read.sonar.range().min_m, 0.0);
  EXPECT_DOUBLE_EQ(read.sonar.range().resolution_m, reference.sonar.range().resolution_m);
  EXPECT_EQ(read.sonar.bearings().centres(), reference.sonar.bearings().centres());
  EXPECT_DOUBLE_EQ(read.sonar.verticalAperture(), reference.sonar.verticalAperture());
  ASSERT_EQ(read.frames.size(), times_ns.size());
  for (std::size_t k = 0; k < times_ns.size(); ++k) {
    // Nanoseconds as double seconds near 10 s: 2e-15 s rounding.
    EXPECT_NEAR(read.frames[k].time_s, static_cast<double>(times_ns[k]) * 1e-9, 1e-9) << k;
    const Frame frame = loadFrame(read, k);
    ASSERT_EQ(frame.image.size(), reference.image.size());
    EXPECT_EQ(cv::norm(frame.image, reference.image, cv::NORM_INF), 0.0) << "frame " << k;
  }
}

class RawOculusBags : public ::testing::TestWithParam<BagFormat> {};

TEST_P(RawOculusBags, ReadAsTheOculusReaderReadsTheSameBytesStampedByTheirHeaders) {
  const test::ScratchDir dir;
  const std::vector<std::uint8_t> ping = test::readBytes(test::oculusFixture().string());
  const RawBag bag =
      writeRawDataBag(dir, GetParam(), GetParam() == BagFormat::Db3 ? "raw.db3" : "raw.mcap", ping);
  const OculusReference reference = oculusReference(ping);

  const Mission read = openMission(bag.path);
  expectSameFrames(read, reference, bag.stamps_ns);
  // info lists the topic as Oculus sonar pings and says what it skipped.
  EXPECT_TRUE(anyContains(read.contents, {"topic /oculus/raw_data", "Oculus sonar pings"}));
  EXPECT_TRUE(anyContains(read.contents, {"1 messages", "Oculus message id 0x15, not a ping"}));
  EXPECT_TRUE(anyContains(read.contents, {"3 messages", "hold no Oculus message"}));
  EXPECT_FALSE(anyContains(read.warnings, {"skipped"})) << read.warnings.front();

  // --time-source receive: the bag's receive times.
  OpenOptions receive;
  receive.bag.time = BagTime::Receive;
  expectSameFrames(openMission(bag.path, receive), reference, bag.receive_ns);
}

INSTANTIATE_TEST_SUITE_P(RosBag, RawOculusBags,
                         ::testing::Values(BagFormat::Mcap, BagFormat::McapUnchunked,
                                           BagFormat::Db3),
                         [](const auto& param_info) {
                           std::string name(toString(param_info.param));
                           std::erase(name, '-');
                           return name;
                         });

TEST(RosBagOculus, AByteArrayWithoutHeaderIsFoundByContentAndTimedByTheBag) {
  const test::ScratchDir dir;
  const std::vector<std::uint8_t> ping = test::readBytes(test::oculusFixture().string());
  for (const BagFormat format : {BagFormat::Mcap, BagFormat::Db3}) {
    const auto path = dir.path() / (format == BagFormat::Db3 ? "array.db3" : "array.mcap");
    std::vector<BagMessageSpec> messages;
    std::vector<std::int64_t> receive;
    for (int k = 0; k < 2; ++k) {
      receive.push_back(5'000'000'000 + k * 100'000'000LL);
      messages.push_back({0, receive.back(), multiArrayMessage(ping)});
    }
    // A type name nobody hard-codes: only the content says it is an Oculus ping.
    writeBagMessages(path, format,
                     {{"/sonar/bytes", "std_msgs/msg/UInt8MultiArray", kMultiArrayDefinition}},
                     messages);
    const Mission read = openMission(path);
    expectSameFrames(read, oculusReference(ping), receive);
    EXPECT_TRUE(anyContains(read.contents, {"2 pings in messages without a std_msgs/Header"}));
  }
}

TEST(RosBagOculus, ACutPingIsSkippedAndNamedByBagTopicAndMessage) {
  const test::ScratchDir dir;
  const std::vector<std::uint8_t> ping = test::readBytes(test::oculusFixture().string());
  for (const BagFormat format : {BagFormat::Mcap, BagFormat::Db3}) {
    const std::string name = format == BagFormat::Db3 ? "cut.db3" : "cut.mcap";
    const RawBag bag = writeRawDataBag(dir, format, name, ping, true);
    const Mission read = openMission(bag.path);
    // The other two pings are read; the cut one (the bag's fourth message) is reported.
    expectSameFrames(read, oculusReference(ping), bag.stamps_ns);
    const std::string message = format == BagFormat::Db3 ? "message id 4" : "message 3 (";
    EXPECT_TRUE(anyContains(read.warnings,
                            {name, "topic /oculus/raw_data", message, "Oculus message byte 10",
                             "payloadSize 182000 runs past the end", "ping skipped"}))
        << ::testing::PrintToString(read.warnings);
  }
}

TEST(RosBagOculus, PingsOfAnotherGeometryOrScaleAreLeftOutAndCounted) {
  const test::ScratchDir dir;
  test::OculusPingSpec small;
  small.gamma = 127;
  std::vector<BagMessageSpec> messages;
  const auto add = [&](std::int64_t seconds) {
    const std::int64_t ns = seconds * 1'000'000'000;
    messages.push_back({0, ns, rawDataMessage(ns, 1, test::encodeOculusPing(small))});
  };
  add(1);
  small.n_beams = 32;  // another geometry
  add(2);
  small.n_beams = 16;
  small.gamma = 0;  // another scale: linear samples
  add(3);
  const auto path = dir.path() / "mixed.mcap";
  writeBagMessages(path, BagFormat::Mcap,
                   {{"/oculus/raw_data", "apl_msgs/msg/RawData", kRawDataDefinition}}, messages);
  const Mission read = openMission(path);
  EXPECT_EQ(read.frames.size(), 1U);
  EXPECT_EQ(read.sonar.cols(), 16);
  EXPECT_EQ(read.sonar.intensityScale(), IntensityScale::gamma(0.498, 255.0));
  EXPECT_TRUE(anyContains(read.warnings, {"mixed.mcap", "topic /oculus/raw_data",
                                          "2 pings of another", "gamma 0.498"}));
}

TEST(RosBagOculus, FindsTheOculusFieldOnlyWhereACountIntroducesTheMagic) {
  const std::vector<std::uint8_t> header = test::encodeOculusMessage(0x23, 0, {});
  CdrWriter with;
  with.write(static_cast<std::uint8_t>(7));
  with.writeCount(header.size());
  with.writeBytes(header);
  const auto field = findOculusField(with.bytes());
  ASSERT_TRUE(field);
  EXPECT_EQ(field->offset, 12U);  // 4 encapsulation + 1 byte padded to 4 + the count
  EXPECT_EQ(field->size, 16U);
  // The magic in a field too short for an Oculus header, or behind a count larger than the
  // bytes left, is no Oculus message.
  CdrWriter text;
  text.writeString("SO");
  EXPECT_FALSE(findOculusField(text.bytes()));
  CdrWriter overlong;
  overlong.writeCount(100);
  overlong.writeBytes(header);
  EXPECT_FALSE(findOculusField(overlong.bytes()));
}

}  // namespace
}  // namespace sonarcarve
