// sensor_msgs/NavSatFix (io/rosbag/ros_messages.h) and the track of fixes (io/rosbag/
// bag_geofix.h): the message round trip, empty and cut messages refused naming the byte, fixes
// without a fix or with NaN left out and counted, none left an error, and the attitude taken
// from the pose topic at each fix's time, turned to grid north. geographic_msgs GeoPoint and
// GeoPointStamped: the message round trip, the origin placed on the grid, and a bag written
// with its origin as a GeoPointStamped read back to the mission's origin, CRS and track.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "common/angles.h"
#include "common/error.h"
#include "io/frame_source.h"
#include "io/rosbag/bag_geofix.h"
#include "io/rosbag/bag_writer.h"
#include "io/rosbag/ros_messages.h"
#include "sonar/attitude.h"
#include "support/bag_fixtures.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

using test::expectError;

NavSatFixMsg fixAt(double latitude, double longitude, double altitude, std::int8_t status = 0) {
  NavSatFixMsg f;
  f.header = {1'500'000'000, "gps"};
  f.status = status;
  f.service = 1;
  f.latitude_deg = latitude;
  f.longitude_deg = longitude;
  f.altitude_m = altitude;
  return f;
}

TEST(NavSatFix, RoundTripsThroughCdr) {
  const NavSatFixMsg sent = fixAt(43.000012345678, 3.7, -12.25, 2);
  const std::vector<std::uint8_t> bytes = encodeNavSatFix(sent);
  const NavSatFixMsg got = decodeNavSatFix(bytes, "bag", "message 3");
  EXPECT_EQ(got.header.stamp_ns, sent.header.stamp_ns);
  EXPECT_EQ(got.header.frame_id, "gps");
  EXPECT_EQ(got.status, 2);
  EXPECT_EQ(got.service, 1);
  EXPECT_EQ(got.latitude_deg, sent.latitude_deg);
  EXPECT_EQ(got.longitude_deg, sent.longitude_deg);
  EXPECT_EQ(got.altitude_m, sent.altitude_m);
  EXPECT_EQ(rosMessageKind("sensor_msgs/msg/NavSatFix"), RosMessageKind::GeoFix);
  EXPECT_EQ(rosMessageKind("sensor_msgs/NavSatFix"), RosMessageKind::GeoFix);
  EXPECT_NE(rosMessageDefinition(kNavSatFixType).find("MSG: sensor_msgs/NavSatStatus"),
            std::string::npos);
}

TEST(NavSatFix, EmptyAndCutMessagesAreRefusedNamingTheByte) {
  const std::vector<std::uint8_t> bytes = encodeNavSatFix(fixAt(43, 3, 0));
  expectError([] { decodeNavSatFix({}, "bag", "message 1"); }, {"bag", "message 1"});
  for (std::size_t cut : {std::size_t{6}, std::size_t{20}, std::size_t{40}, bytes.size() - 1}) {
    const std::vector<std::uint8_t> part(bytes.begin(), bytes.begin() + cut);
    expectError([&] { decodeNavSatFix(part, "bag", "message 2"); }, {"bag", "message 2", "byte"});
  }
}

TimedFix timed(double t, const NavSatFixMsg& f) {
  return {t, f, "message at " + std::to_string(t)};
}

TEST(BagGeoFix, FixesWithoutAFixOrNotFiniteAreLeftOutAndCounted) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<TimedFix> fixes = {
      timed(1, fixAt(43, 3, -10)),     timed(2, fixAt(43.0001, 3, -10, kNavSatStatusNoFix)),
      timed(3, fixAt(nan, 3, -10)),    timed(4, fixAt(43, 3, nan)),
      timed(5, fixAt(91, 3, -10)),     timed(6, fixAt(43.0002, 3, -11)),
      timed(6, fixAt(43.0003, 3, -11))};
  const BagGeoNavigation nav = bagGeoNavigation(fixes, std::nullopt, "", "bag.mcap", "/fix");
  EXPECT_EQ(nav.crs, "EPSG:32631");
  EXPECT_EQ(nav.no_fix, 1u);
  EXPECT_EQ(nav.not_finite, 3u);
  EXPECT_EQ(nav.duplicates, 1u);
  ASSERT_EQ(nav.track.samples().size(), 2u);
  EXPECT_EQ(nav.track.samples()[1].position_m.z(), 11.0);  // down = -altitude
  // 0.0002 deg of latitude: 22.2 m north on the grid.
  EXPECT_NEAR(nav.track.samples()[1].position_m.x() - nav.first_fix_ned_m.x(), 22.2, 0.1);
  EXPECT_EQ(leftOutFixes(nav),
            "1 with status STATUS_NO_FIX, 3 with a latitude, longitude or altitude not finite or "
            "off the Earth, 1 whose time did not increase");
}

TEST(BagGeoFix, NoUsableFixIsAnErrorSayingWhy) {
  std::vector<TimedFix> fixes = {timed(1, fixAt(43, 3, 0, kNavSatStatusNoFix)),
                                 timed(2, fixAt(43, 3, 0, kNavSatStatusNoFix))};
  expectError([&] { bagGeoNavigation(fixes, std::nullopt, "", "bag.mcap", "/fix"); },
              {"bag.mcap: topic /fix", "no usable sensor_msgs/NavSatFix of 2",
               "2 with status STATUS_NO_FIX", "expected fixes with finite latitude"});
}

TEST(BagGeoFix, AttitudeFromThePosesAtEachFixTurnedToGridNorth) {
  // Heading east from true north all along, 0 to 10 s; at 5 E, 2 degrees east of UTM 31N's
  // central meridian, true north lies west of grid north.
  std::vector<NavSample> poses(2);
  poses[0].time_s = 0.0;
  poses[1].time_s = 10.0;
  for (NavSample& p : poses) {
    p.q_world_vehicle = quaternionFromRollPitchYaw({0.0, 0.0, degToRad(90.0)});
  }
  const std::optional<NavTrack> attitude{NavTrack(poses)};
  std::vector<TimedFix> fixes = {timed(5, fixAt(43, 5, 0)), timed(20, fixAt(43, 5, 0))};
  const BagGeoNavigation nav = bagGeoNavigation(fixes, attitude, "", "bag.mcap", "/fix");
  ASSERT_EQ(nav.track.samples().size(), 1u);
  EXPECT_EQ(nav.outside_attitude, 1u);
  const double yaw = rollPitchYawFromQuaternion(nav.track.samples()[0].q_world_vehicle).yaw_rad;
  // Grid convergence at (43 N, 5 E) on UTM 31N: 1.36 degrees (docs/conventions.md).
  EXPECT_NEAR(radToDeg(yaw), 90.0 - 1.364, 0.01);
}

TEST(GeoPoint, RoundTripsThroughCdrStampedOrNot) {
  const GeoPointMsg sent{{1'500'000'000, "map"}, 43.000012345678, 5.25, -7.5};
  const std::vector<std::uint8_t> bytes = encodeGeoPointStamped(sent);
  const GeoPointMsg got = decodeGeoPoint(kGeoPointStampedType, bytes, "bag", "message 1");
  EXPECT_EQ(got.header.stamp_ns, sent.header.stamp_ns);
  EXPECT_EQ(got.latitude_deg, sent.latitude_deg);
  EXPECT_EQ(got.longitude_deg, sent.longitude_deg);
  EXPECT_EQ(got.altitude_m, sent.altitude_m);
  // A GeoPoint alone: the three numbers after the CDR encapsulation header.
  const std::vector<std::uint8_t> point(bytes.begin(), bytes.begin() + 4);
  std::vector<std::uint8_t> bare = point;
  bare.insert(bare.end(), bytes.end() - 24, bytes.end());
  const GeoPointMsg alone = decodeGeoPoint("geographic_msgs/msg/GeoPoint", bare, "bag", "m");
  EXPECT_EQ(alone.latitude_deg, sent.latitude_deg);
  EXPECT_EQ(alone.altitude_m, sent.altitude_m);
  EXPECT_EQ(rosMessageKind("geographic_msgs/msg/GeoPoint"), RosMessageKind::GeoOrigin);
  EXPECT_EQ(rosMessageKind("geographic_msgs/GeoPointStamped"), RosMessageKind::GeoOrigin);
  EXPECT_NE(rosMessageDefinition(kGeoPointStampedType).find("MSG: geographic_msgs/GeoPoint"),
            std::string::npos);
  for (std::size_t cut : {std::size_t{0}, std::size_t{10}, bytes.size() - 1}) {
    const std::vector<std::uint8_t> part(bytes.begin(), bytes.begin() + cut);
    expectError([&] { decodeGeoPoint(kGeoPointStampedType, part, "bag", "message 2"); },
                {"bag", "message 2"});
  }
}

TEST(GeoPoint, TheOriginIsPlacedOnItsUtmZoneWithTheGridConvergence) {
  const BagGeoOrigin origin = bagGeoOrigin({{}, 43.0, 5.0, -12.0}, "", "bag.mcap", "topic /o");
  EXPECT_EQ(origin.crs, "EPSG:32631");
  EXPECT_EQ(origin.ned_m.z(), 12.0);  // down = -altitude
  // 2 degrees east of the central meridian: 163 km east of the false easting 500 km.
  EXPECT_NEAR(origin.ned_m.y(), 663000.0, 1000.0);
  EXPECT_NEAR(radToDeg(origin.true_north_bearing_rad), -1.364, 0.01);
  expectError(
      [] {
        bagGeoOrigin({{}, 95.0, 5.0, 0.0}, "", "bag.mcap", "topic /o, message 1");
      },
      {"bag.mcap: topic /o, message 1: latitude 95", "expected finite WGS84 degrees"});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expectError(
      [&] {
        bagGeoOrigin({{}, 43.0, nan, 0.0}, "", "bag.mcap", "topic /o");
      },
      {"bag.mcap: topic /o", "expected finite"});
}

// The bag fixtures' mission placed 160 km east of UTM 31N's central meridian (a grid
// convergence of 1.1 degrees, which the odometry's frame, aligned with true north, must undo).
Mission placedMission() {
  Mission mission = test::memoryMission(3, test::countsPattern);
  mission.crs = "EPSG:32631";
  mission.origin_ned_m = Eigen::Vector3d(4762000.0, 660000.0, 4.0);
  return mission;
}

void expectSameTrack(const NavTrack& read, const NavTrack& written) {
  ASSERT_EQ(read.samples().size(), written.samples().size());
  for (std::size_t i = 0; i < read.samples().size(); ++i) {
    const NavSample& a = read.samples()[i];
    const NavSample& b = written.samples()[i];
    EXPECT_LT((a.position_m - b.position_m).norm(), 1e-6) << "sample " << i;
    EXPECT_LT(a.q_world_vehicle.angularDistance(b.q_world_vehicle), 1e-9) << "sample " << i;
  }
}

TEST(GeoPoint, ABagsOriginIsTheMissionOriginAsMissionYamlsIs) {
  test::ScratchDir dir;
  const Mission written = placedMission();
  BagWriteOptions options;
  options.origin_topic = "/origin";
  writeRosBag(written, dir.path() / "origin.mcap", options);
  const Mission read = openMission(dir.path() / "origin.mcap");
  EXPECT_EQ(read.crs, "EPSG:32631");
  // PROJ's round trip through WGS84: well under a millimetre.
  EXPECT_LT((read.origin_ned_m - written.origin_ned_m).norm(), 1e-6);
  expectSameTrack(read.nav, written.nav);
  bool said = false;
  for (const std::string& line : read.contents) {
    said = said || line.find("origin topic /origin (geographic_msgs/msg/GeoPointStamped)") == 0;
  }
  EXPECT_TRUE(said);

  // Beside NavSatFix positions, the GeoPoint is the origin instead of the first fix.
  options.fix_topic = "/fix";
  writeRosBag(written, dir.path() / "fix.mcap", options);
  const Mission on_fixes = openMission(dir.path() / "fix.mcap");
  EXPECT_LT((on_fixes.origin_ned_m - written.origin_ned_m).norm(), 1e-6);
  expectSameTrack(on_fixes.nav, written.nav);

  // Another topic asked for by name, and a topic of another type, are refused.
  OpenOptions wrong;
  wrong.bag.origin_topic = "/odometry";
  expectError([&] { openMission(dir.path() / "origin.mcap", wrong); },
              {"origin.mcap: topic /odometry", "(--origin-topic): expected geographic_msgs"});
}

}  // namespace
}  // namespace sonarcarve
