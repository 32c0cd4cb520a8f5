// ROS 2 bags read back: a mission written by our bag writer in every storage comes back with
// the same frames (sample for sample within the dtype's rounding), times, sonar geometry,
// navigation and mounting; the conventions are checked on hand-made bags whose answer is
// known (a target to starboard must land to starboard).
#include <gtest/gtest.h>
#include <sqlite3.h>
#include <zstd.h>

#include <cmath>
#include <cstring>

#include "common/angles.h"
#include "io/frame_source.h"
#include "io/rosbag/bag_navigation.h"
#include "io/rosbag/bag_sonar.h"
#include "io/rosbag/bag_writer.h"
#include "io/rosbag/cdr.h"
#include "io/rosbag/mcap_writer.h"
#include "io/rosbag/ros_bag.h"
#include "io/rosbag/ros_frames.h"
#include "io/rosbag/ros_messages.h"
#include "support/bag_fixtures.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

using test::memoryMission;

std::filesystem::path writeBag(const test::ScratchDir& dir, const Mission& mission,
                               BagWriteOptions options, const std::string& name) {
  const auto path = dir.path() / name;
  const BagWriteReport report = writeRosBag(mission, path, options);
  EXPECT_EQ(report.frames, mission.frames.size());
  EXPECT_EQ(report.poses, mission.nav.samples().size());
  return path;
}

double maxDifference(const cv::Mat& a, const cv::Mat& b) {
  return cv::norm(a, b, cv::NORM_INF);
}

class BagStorages : public ::testing::TestWithParam<BagFormat> {};

TEST_P(BagStorages, ReadBackToTheSameFramesPosesAndMounting) {
  const test::ScratchDir dir;
  const Mission original = memoryMission(5, test::countsPattern);
  BagWriteOptions options;
  options.format = GetParam();
  options.chunk_bytes = 4000;  // several chunks: each holds about one frame
  const auto path =
      writeBag(dir, original, options, GetParam() == BagFormat::Db3 ? "bag.db3" : "bag.mcap");
  ASSERT_TRUE(looksLikeRosBag(path));
  const Mission read = openMission(path);
  EXPECT_NE(read.source->kind().find("ROS 2 bag"), std::string::npos);
  EXPECT_TRUE(read.warnings.empty()) << read.warnings.front();

  // Geometry: ranges go through float32 bin centres (relative rounding 6e-8 of 2.5 m).
  const SonarModel& a = original.sonar;
  const SonarModel& b = read.sonar;
  ASSERT_EQ(b.rows(), a.rows());
  ASSERT_EQ(b.cols(), a.cols());
  EXPECT_NEAR(b.range().min_m, a.range().min_m, 1e-6);
  EXPECT_NEAR(b.range().resolution_m, a.range().resolution_m, 1e-7);
  for (int c = 0; c < a.cols(); ++c) {
    EXPECT_NEAR(b.bearings().centre(c), a.bearings().centre(c), 1e-12) << c;
  }
  // The aperture travels as float32 radians.
  EXPECT_NEAR(b.verticalAperture(), a.verticalAperture(), 1e-7);

  ASSERT_EQ(read.frames.size(), original.frames.size());
  for (std::size_t k = 0; k < original.frames.size(); ++k) {
    EXPECT_NEAR(read.frames[k].time_s, original.frames[k].time_s, 1e-9) << k;
    const Frame fa = loadFrame(original, k);
    const Frame fb = loadFrame(read, k);
    EXPECT_EQ(maxDifference(fa.image, fb.image), 0.0) << "frame " << k;  // uint16: exact
  }

  // Poses and mounting travel as float64: equal to rounding of the frame conversions.
  ASSERT_EQ(read.nav.samples().size(), original.nav.samples().size());
  for (std::size_t k = 0; k < original.nav.samples().size(); ++k) {
    const NavSample& sa = original.nav.samples()[k];
    const NavSample& sb = read.nav.samples()[k];
    EXPECT_NEAR(sb.time_s, sa.time_s, 1e-9);
    EXPECT_LT((sb.position_m - sa.position_m).norm(), 1e-12) << k;
    EXPECT_LT(sb.q_world_vehicle.angularDistance(sa.q_world_vehicle), 1e-9) << k;
  }
  const Eigen::Isometry3d ma = original.mounting.T_vehicle_sonar();
  const Eigen::Isometry3d mb = read.mounting.T_vehicle_sonar();
  EXPECT_LT((ma.translation() - mb.translation()).norm(), 1e-12);
  EXPECT_LT(Eigen::Quaterniond(ma.linear()).angularDistance(Eigen::Quaterniond(mb.linear())), 1e-9);
}

INSTANTIATE_TEST_SUITE_P(RosBag, BagStorages,
                         ::testing::Values(BagFormat::Mcap, BagFormat::McapLz4, BagFormat::McapNone,
                                           BagFormat::McapUnchunked, BagFormat::Db3),
                         [](const auto& param_info) {
                           std::string name(toString(param_info.param));
                           std::erase(name, '-');
                           return name;
                         });

TEST(RosBag, SamplesComeBackWithinTheirDtypeRounding) {
  const test::ScratchDir dir;
  // Fractional intensities: float32 keeps them, uint8 rounds them to the nearest count.
  const Mission original = memoryMission(2, [](std::size_t f, int r, int c) {
    return static_cast<float>(f * 3 + r * 0.37 + c * 1.91);
  });
  for (const SonarDtype dtype : {SonarDtype::Float32, SonarDtype::UInt8, SonarDtype::UInt16}) {
    BagWriteOptions options;
    options.dtype = dtype;
    const auto path = writeBag(dir, original, options,
                               "dtype" + std::to_string(static_cast<int>(dtype)) + ".mcap");
    const Mission read = openMission(path);
    const double rounding = dtype == SonarDtype::Float32 ? 0.0 : 0.5;
    for (std::size_t k = 0; k < 2; ++k) {
      EXPECT_LE(maxDifference(loadFrame(original, k).image, loadFrame(read, k).image), rounding)
          << "dtype " << static_cast<int>(dtype) << " frame " << k;
    }
  }
}

TEST(RosBag, LayoutAxesAndClockOptionsReadWhatTheWriterChose) {
  const test::ScratchDir dir;
  const Mission original = memoryMission(3, test::countsPattern);
  BagWriteOptions options;
  options.layout = ImageLayout::BeamMajor;
  options.axes = SonarAxes::XForward;
  options.receive_delay_s = 0.25;
  const auto path = writeBag(dir, original, options, "other.mcap");

  OpenOptions open;
  open.bag.layout = ImageLayout::BeamMajor;
  open.bag.time = BagTime::Receive;
  const Mission read = openMission(path, open);  // axes: auto finds X forward
  EXPECT_EQ(maxDifference(loadFrame(original, 1).image, loadFrame(read, 1).image), 0.0);
  EXPECT_NEAR(read.frames[1].time_s, original.frames[1].time_s + 0.25, 1e-9);
  bool said_axes = false;
  for (const std::string& line : read.contents) {
    said_axes |= line.find("sonar axes x-forward (chosen") != std::string::npos;
  }
  EXPECT_TRUE(said_axes);

  // The default layout reads the same bytes into other pixels: the option matters.
  const Mission wrong_layout = openMission(path);
  EXPECT_GT(maxDifference(loadFrame(original, 1).image, loadFrame(wrong_layout, 1).image), 0.0);
  // Forcing the message comment's axes on X-forward directions: every beam points at +-90 deg.
  open.bag.axes = SonarAxes::ZForward;
  test::expectError([&] { openMission(path, open); },
                    {"other.mcap", "beam_directions", "repeats a bearing"});
}

// A bag made by hand, as another recorder would: a vehicle at the ENU origin with zero yaw
// (facing east), the sonar mounted at the vehicle origin, one ping with a single bright sample
// at 5 m on the beam 20 degrees to starboard.
std::filesystem::path starboardTargetBag(const test::ScratchDir& dir, SonarAxes axes,
                                         const std::string& name) {
  constexpr int kBeams = 31;
  constexpr int kRanges = 100;
  ProjectedSonarImageMsg image;
  image.header = {1'000'000'000, "sonar_link"};
  int target_beam = -1;
  for (int b = 0; b < kBeams; ++b) {
    const double bearing = degToRad(-30.0 + 2.0 * b);
    if (b == 25) {
      target_beam = b;  // +20 degrees
    }
    // Z forward, X up, Y starboard; or X forward, Y port, Z up.
    image.beam_directions.push_back(
        axes == SonarAxes::ZForward ? Eigen::Vector3d(0, std::sin(bearing), std::cos(bearing))
                                    : Eigen::Vector3d(std::cos(bearing), -std::sin(bearing), 0));
  }
  for (int r = 0; r < kRanges; ++r) {
    image.ranges_m.push_back(0.05F + 0.1F * r);
  }
  std::vector<std::uint8_t> data(kBeams * kRanges, 0);
  data[static_cast<std::size_t>(50 * kBeams + target_beam)] = 200;  // 5.05 m
  image.dtype = 0;
  image.beam_count = kBeams;
  image.data = data;

  RosPoseMsg pose;
  pose.header = {0, "odom"};
  pose.child_frame_id = "base_link";
  RosPoseMsg later = pose;
  later.header.stamp_ns = 2'000'000'000;
  RosTransformMsg mount;
  mount.header = {0, "base_link"};
  mount.child_frame_id = "sonar_link";
  if (axes == SonarAxes::ZForward) {
    // The message's sonar frame (Z forward, X up) in the FLU body: Z -> x, X -> z, Y -> -y.
    Eigen::Matrix3d R;
    R << 0, 0, 1, 0, -1, 0, 1, 0, 0;
    mount.rotation = Eigen::Quaterniond(R);
  }
  McapWriter writer(McapChunks::Lz4, 1 << 20);
  const std::vector<std::pair<std::string, std::string>> topics = {
      {"/oculus/sonar_image", kProjectedSonarImageType},
      {"/odom", kOdometryType},
      {"/tf_static", kTfMessageType}};
  for (std::uint16_t t = 0; t < 3; ++t) {
    writer.addSchema(t + 1, topics[t].second, rosMessageDefinition(topics[t].second));
    writer.addChannel(t + 1, t + 1, topics[t].first);
  }
  writer.addMessage(3, 0, 0, encodeTfMessage({mount}));
  writer.addMessage(2, 0, 0, encodeOdometry(pose));
  writer.addMessage(1, 1'000'000'000, 1'000'000'000, encodeProjectedSonarImage(image));
  writer.addMessage(2, 2'000'000'000, 2'000'000'000, encodeOdometry(later));
  const auto bytes = writer.finish();
  const auto path = dir.path() / name;
  test::writeText(path, std::string(bytes.begin(), bytes.end()));
  return path;
}

TEST(RosBag, ATargetToStarboardLandsToStarboardInEitherAxisConvention) {
  const test::ScratchDir dir;
  for (const SonarAxes axes : {SonarAxes::ZForward, SonarAxes::XForward}) {
    const auto path = starboardTargetBag(dir, axes, std::string(toString(axes)) + ".mcap");
    for (const SonarAxes chosen : {SonarAxes::Auto, axes}) {
      OpenOptions options;
      options.bag.axes = chosen;
      const Mission mission = openMission(path, options);
      const Frame frame = loadFrame(mission, 0);
      cv::Point at;
      cv::minMaxLoc(frame.image, nullptr, nullptr, nullptr, &at);
      const Polar polar = mission.sonar.pixelCentre({at.y, at.x});
      EXPECT_NEAR(radToDeg(polar.bearing_rad), 20.0, 1e-9) << toString(axes);
      // Facing east (ENU yaw 0), 20 degrees to starboard is east and a little south.
      const Eigen::Vector3d p_world =
          mission.nav.T_world_sonar(frame.time_s, mission.mounting.T_vehicle_sonar()) *
          pointFromPolar(polar);
      EXPECT_NEAR(p_world.x(), -5.05 * std::sin(degToRad(20)), 1e-6) << toString(axes);
      EXPECT_NEAR(p_world.y(), 5.05 * std::cos(degToRad(20)), 1e-6) << toString(axes);
      EXPECT_NEAR(p_world.z(), 0.0, 1e-6) << toString(axes);
    }
  }
}

// The older acoustic_msgs/SonarImage, written field by field as its definition says: 31
// azimuths from -30 to +30 degrees (positive to starboard), 100 ranges, uint16 data
// azimuth-major, one bright sample at 5.05 m on the beam at +20 degrees.
std::vector<std::uint8_t> legacySonarImage() {
  CdrWriter out;
  out.write(std::int32_t{1});
  out.write(std::uint32_t{0});
  out.writeString("sonar_ned");
  out.write(900e3F);
  out.write(1500.0F);
  out.write(0.03F);
  out.write(static_cast<float>(degToRad(14.0)));
  std::vector<float> azimuths;
  for (int b = 0; b < 31; ++b) {
    azimuths.push_back(static_cast<float>(degToRad(-30.0 + 2.0 * b)));
  }
  out.writeSequence(azimuths);
  out.writeCount(0);  // elevation_angles
  std::vector<float> ranges;
  for (int r = 0; r < 100; ++r) {
    ranges.push_back(0.05F + 0.1F * r);
  }
  out.writeSequence(ranges);
  out.writeBool(false);
  out.write(std::uint8_t{2});
  std::vector<std::uint8_t> data(31 * 100 * 2, 0);
  const std::uint16_t bright = 40000;
  std::memcpy(data.data() + (25 * 100 + 50) * 2, &bright, 2);  // azimuth-major
  out.writeCount(data.size());
  out.writeBytes(data);
  return out.bytes();
}

TEST(RosBag, TheOlderSonarImageIsReadInItsOwnFrameAndLayout) {
  const test::ScratchDir dir;
  McapWriter writer(McapChunks::Zstd, 1 << 20);
  writer.addSchema(1, "acoustic_msgs/msg/SonarImage", "");
  writer.addChannel(1, 1, "/sonar");
  writer.addMessage(1, 1'000'000'000, 1'000'000'000, legacySonarImage());
  const auto bytes = writer.finish();
  const auto path = dir.path() / "legacy.mcap";
  test::writeText(path, std::string(bytes.begin(), bytes.end()));
  OpenOptions options;
  options.bag.layout = ImageLayout::RangeMajor;  // does not apply to this type
  const Mission mission = openMission(path, options);
  EXPECT_NEAR(radToDeg(mission.sonar.verticalAperture()), 14.0, 1e-5);
  const Frame frame = loadFrame(mission, 0);
  cv::Point at;
  double peak = 0.0;
  cv::minMaxLoc(frame.image, nullptr, &peak, nullptr, &at);
  EXPECT_EQ(peak, 40000.0);
  const Polar polar = mission.sonar.pixelCentre({at.y, at.x});
  EXPECT_NEAR(radToDeg(polar.bearing_rad), 20.0, 1e-5);  // float32 azimuths
  EXPECT_NEAR(polar.range_m, 5.05, 1e-5);
}

// A message of 3 beams 10 degrees apart and 4 range bins centred from 1.05 m, 0.1 m apart.
ProjectedSonarImageMsg threeBeamMessage() {
  ProjectedSonarImageMsg msg;
  for (int b = 0; b < 3; ++b) {
    msg.beam_directions.push_back(
        beamDirectionOfBearing(degToRad(10.0 * (b - 1)), SonarAxes::ZForward));
  }
  msg.beam_count = 3;
  msg.ranges_m = {1.05F, 1.15F, 1.25F, 1.35F};
  return msg;
}

TEST(RosBag, RangesAreBinCentresAndAFirstCentreAtZeroIsSaid) {
  ProjectedSonarImageMsg msg = threeBeamMessage();
  BagSonarGeometry g = bagSonarGeometry(msg, SonarAxes::Auto, ImageLayout::RangeMajor, std::nullopt,
                                        "s", "bag", "message 0");
  EXPECT_NEAR(g.sonar.range().min_m, 1.0, 1e-6);  // centres: the bins start half a bin before
  EXPECT_NEAR(g.sonar.range().resolution_m, 0.1, 1e-6);
  EXPECT_NEAR(radToDeg(g.sonar.verticalAperture()), kBagDefaultApertureDeg, 1e-9);
  msg.ranges_m = {0.0F, 0.1F, 0.2F, 0.3F};
  g = bagSonarGeometry(msg, SonarAxes::Auto, ImageLayout::RangeMajor, std::nullopt, "s", "bag",
                       "message 0");
  EXPECT_EQ(g.sonar.range().min_m, 0.0);
  bool said = false;
  for (const std::string& note : g.notes) {
    said |= note.find("less than half a bin") != std::string::npos;
  }
  EXPECT_TRUE(said);
  msg.ranges_m = {1.0F, 1.1F, 1.3F, 1.4F};
  test::expectError(
      [&] {
        bagSonarGeometry(msg, SonarAxes::Auto, ImageLayout::RangeMajor, std::nullopt, "s", "bag",
                         "message 0");
      },
      {"bag", "message 0", "ranges[", "expected equally spaced range bins"});
}

// The first message sets the bag's geometry; a later one out of any sonar (an aperture of
// nothing, a sound speed of 1e30) is refused, so that the reader skips and reports it.
TEST(RosBag, ALaterMessageIsHeldToTheRangesOfItsApertureAndSoundSpeed) {
  ProjectedSonarImageMsg msg = threeBeamMessage();
  msg.tx_beamwidths_rad = {0.35F, 0.35F, 0.35F};
  const std::vector<std::uint8_t> data(3 * 4 * sonarDtypeSize(msg.dtype), 0);
  msg.data = data;
  const BagSonarGeometry g = bagSonarGeometry(msg, SonarAxes::Auto, ImageLayout::RangeMajor,
                                              std::nullopt, "s", "bag", "message 0");
  checkBagSonarMessage(msg, g, "bag", "message 1");
  ProjectedSonarImageMsg later = msg;
  later.tx_beamwidths_rad = {1e-30F, 1e-30F, 1e-30F};
  test::expectError([&] { checkBagSonarMessage(later, g, "bag", "message 2"); },
                    {"bag", "message 2", "ping_info.tx_beamwidths: expected 0.1 to 180"});
  // --aperture-deg overrides every message's: their tx_beamwidths are not read.
  const BagSonarGeometry given = bagSonarGeometry(msg, SonarAxes::Auto, ImageLayout::RangeMajor,
                                                  12.0, "s", "bag", "message 0");
  checkBagSonarMessage(later, given, "bag", "message 2");
  later = msg;
  later.sound_speed_mps = 1e30F;
  test::expectError([&] { checkBagSonarMessage(later, g, "bag", "message 3"); },
                    {"bag", "message 3", "sound_speed: expected 1000 to 2000 m/s"});
  later.sound_speed_mps = 1450.0F;
  checkBagSonarMessage(later, g, "bag", "message 3");
}

TEST(RosBag, PoseFramesFollowREP103UnlessTheirNamesSayNedAndFrd) {
  RosPoseMsg pose;
  pose.position = Eigen::Vector3d(1, 2, 3);
  pose.header.frame_id = "odom";
  pose.child_frame_id = "base_link";
  // ENU and FLU: east 1, north 2, up 3; zero yaw faces east, a heading of 90 degrees.
  const BagNavigation enu = bagNavigation({{0.0, pose}, {1.0, pose}}, "bag", "/odom");
  const NavSample& a = enu.track.samples().front();
  EXPECT_LT((a.position_m - Eigen::Vector3d(2, 1, -3)).norm(), 1e-12);
  const RollPitchYaw rpy = rollPitchYawFromQuaternion(a.q_world_vehicle);
  EXPECT_NEAR(radToDeg(rpy.yaw_rad), 90.0, 1e-9);
  EXPECT_NEAR(rpy.roll_rad, 0.0, 1e-12);
  EXPECT_NEAR(rpy.pitch_rad, 0.0, 1e-12);
  // Names ending in _ned / _frd: taken as they are.
  pose.header.frame_id = "odom_ned";
  pose.child_frame_id = "base_link_frd";
  const BagNavigation ned = bagNavigation({{0.0, pose}, {1.0, pose}, {1.0, pose}}, "bag", "/odom");
  EXPECT_TRUE(ned.conventions.world_ned && ned.conventions.body_frd);
  EXPECT_LT((ned.track.samples().front().position_m - Eigen::Vector3d(1, 2, 3)).norm(), 1e-12);
  EXPECT_LT(
      ned.track.samples().front().q_world_vehicle.angularDistance(Eigen::Quaterniond::Identity()),
      1e-12);
  EXPECT_EQ(ned.duplicates, 1U);  // a repeated time is left out and counted
  EXPECT_EQ(ned.track.samples().size(), 2U);
}

TEST(RosBag, Db3MessagesCompressedOneByOneAreDecompressed) {
  // rosbag2's `--compression-mode message --compression-format zstd`: each row's data is a
  // zstd frame of the CDR bytes.
  const test::ScratchDir dir;
  const Mission original = memoryMission(3, test::countsPattern);
  BagWriteOptions options;
  options.format = BagFormat::Db3;
  const auto path = writeBag(dir, original, options, "compressed.db3");
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  sqlite3_stmt* rows = nullptr;
  sqlite3_prepare_v2(db, "SELECT id, data FROM messages", -1, &rows, nullptr);
  std::vector<std::pair<sqlite3_int64, std::vector<char>>> compressed;
  while (sqlite3_step(rows) == SQLITE_ROW) {
    const auto* data = static_cast<const char*>(sqlite3_column_blob(rows, 1));
    const auto size = static_cast<std::size_t>(sqlite3_column_bytes(rows, 1));
    std::vector<char> frame(ZSTD_compressBound(size));
    frame.resize(ZSTD_compress(frame.data(), frame.size(), data, size, 3));
    compressed.emplace_back(sqlite3_column_int64(rows, 0), std::move(frame));
  }
  sqlite3_finalize(rows);
  sqlite3_stmt* update = nullptr;
  sqlite3_prepare_v2(db, "UPDATE messages SET data = ? WHERE id = ?", -1, &update, nullptr);
  for (const auto& [id, frame] : compressed) {
    sqlite3_reset(update);
    sqlite3_bind_blob(update, 1, frame.data(), static_cast<int>(frame.size()), SQLITE_STATIC);
    sqlite3_bind_int64(update, 2, id);
    ASSERT_EQ(sqlite3_step(update), SQLITE_DONE);
  }
  sqlite3_finalize(update);
  sqlite3_close(db);
  const Mission read = openMission(path);
  ASSERT_EQ(read.frames.size(), 3U);
  EXPECT_EQ(maxDifference(loadFrame(original, 2).image, loadFrame(read, 2).image), 0.0);
  EXPECT_EQ(read.nav.samples().size(), original.nav.samples().size());
}

TEST(RosBag, ABagFolderIsReadThroughItsMetadata) {
  const test::ScratchDir dir;
  const Mission original = memoryMission(2, test::countsPattern);
  const auto folder = dir.path() / "rosbag2_2024_01_01";
  std::filesystem::create_directories(folder);
  BagWriteOptions options;
  options.format = BagFormat::Db3;
  writeBag(dir, original, options, "rosbag2_2024_01_01/rosbag2_2024_01_01_0.db3");
  test::writeText(folder / "metadata.yaml",
                  "rosbag2_bagfile_information:\n  version: 5\n  storage_identifier: sqlite3\n"
                  "  relative_file_paths:\n    - rosbag2_2024_01_01_0.db3\n");
  const Mission read = openMission(folder);
  EXPECT_EQ(read.frames.size(), 2U);
  EXPECT_NE(read.source->kind().find("bag folder of 1 SQLite3 file"), std::string::npos)
      << read.source->kind();
}

}  // namespace
}  // namespace sonarcarve
