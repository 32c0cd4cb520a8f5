// NavSatFix in bags (issue 43): the simulated riser's mission with its navigation in WGS84
// latitude and longitude (60 km east of UTM 31N's central meridian, headings from true north)
// and its bag twin, written by io/rosbag/bag_writer.h with the positions as
// sensor_msgs/NavSatFix and the attitude as Odometry, reconstruct to the same surface: their
// F-scores against the ground truth (moved onto the grid as the navigation was) by `evaluate`
// agree to 0.01, and the bag's outputs carry the CRS.
#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>

#include "common/angles.h"
#include "geo/crs.h"
#include "geo/crs_transform.h"
#include "geo/grid_projection.h"
#include "io/frame_source.h"
#include "io/mesh/point_cloud_ply.h"
#include "io/mission/nav_csv.h"
#include "io/rosbag/bag_writer.h"
#include "sonar/attitude.h"
#include "support/cli_runner.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

using test::quoted;
using test::runCli;

constexpr double kSameFscore = 0.01;
constexpr const char* kGrid = "EPSG:32631";
// The simulator's NED zero on the grid: easting, northing.
const Eigen::Vector2d kZeroEN(560000.0, 4760000.0);

// A PLY in world NED on the grid, in double (6 decimals): the simulator's points moved by
// kZeroEN, with the mesh's triangles when there are.
void writeWorldPly(const std::filesystem::path& from, const std::filesystem::path& to,
                   bool triangles) {
  const PlyMesh mesh = triangles ? readPlyMesh(from) : PlyMesh{readPointCloudPly(from), {}};
  std::ostringstream out;
  out << std::fixed << std::setprecision(6) << "ply\nformat ascii 1.0\nelement vertex "
      << mesh.vertices.positions.size()
      << "\nproperty double x\nproperty double y\nproperty double z\n";
  if (!mesh.triangles.empty()) {
    out << "element face " << mesh.triangles.size() << "\nproperty list uchar int vertex_indices\n";
  }
  out << "end_header\n";
  for (const Eigen::Vector3f& p : mesh.vertices.positions) {
    out << kZeroEN.y() + p.x() << ' ' << kZeroEN.x() + p.y() << ' ' << p.z() << '\n';
  }
  for (const auto& t : mesh.triangles) {
    out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  }
  test::writeText(to, out.str());
}

class BagNavSatFix : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::ScratchDir;
    const auto sim =
        runCli("simulate --scene riser --noise none --max-frames 20 --out " + quoted(path("ned")));
    ASSERT_EQ(sim.exit_code, 0) << sim.output;
    writeGeodeticTwin();
    BagWriteOptions options;
    options.fix_topic = "/gps/fix";
    writeRosBag(openMission(path("geodetic")), path("twin.mcap"), options);
    for (const char* run : {"geodetic", "twin.mcap"}) {
      const auto rec = runCli("reconstruct " + quoted(path(run)) + " --out " +
                              quoted(path(run + std::string(".out"))));
      ASSERT_EQ(rec.exit_code, 0) << rec.output;
    }
    writeWorldPly(path("ned") / "ground_truth.ply", path("truth_world.ply"), true);
    writeWorldPly(path("ned") / "visible_points.ply", path("visible_world.ply"), false);
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }
  static std::filesystem::path path(const std::string& name) { return dir_->path() / name; }

  // The mission with latitude and longitude (PROJ from the grid), headings from true north
  // (the grid heading less true north's grid bearing) and its origin at kZeroEN; its ground
  // truth, in the simulator's frame, left out.
  static void writeGeodeticTwin() {
    test::copyMissionWithoutTruth(path("ned"), path("geodetic"));
    const CrsTransform to_wgs84(kGrid, kWgs84Crs, "test", "crs");
    const GridProjection grid(kWgs84Crs, kGrid, "test", "crs");
    std::ostringstream csv;
    csv.precision(17);
    csv << "time_s,latitude_deg,longitude_deg,down_m,roll_deg,pitch_deg,yaw_deg\n";
    const NavTrack nav = readNavCsv(path("ned") / "nav.csv");
    for (const NavSample& s : nav.samples()) {
      const auto ll =
          to_wgs84.apply({kZeroEN.x() + s.position_m.y(), kZeroEN.y() + s.position_m.x(), 0.0});
      ASSERT_TRUE(ll);
      const double bearing = grid.place(ll->x(), ll->y(), "test", "nav").true_north_bearing_rad;
      const RollPitchYaw rpy = rollPitchYawFromQuaternion(s.q_world_vehicle);
      csv << s.time_s << ',' << ll->y() << ',' << ll->x() << ',' << s.position_m.z() << ','
          << radToDeg(rpy.roll_rad) << ',' << radToDeg(rpy.pitch_rad) << ','
          << radToDeg(rpy.yaw_rad - bearing) << '\n';
    }
    test::writeText(path("geodetic") / "nav.csv", csv.str());
    const auto origin = to_wgs84.apply({kZeroEN.x(), kZeroEN.y(), 0.0});
    ASSERT_TRUE(origin);
    std::ostringstream yaml;
    yaml.precision(17);
    yaml << "origin: {latitude_deg: " << origin->y() << ", longitude_deg: " << origin->x()
         << ", depth_m: 0}\n";
    test::writeText(path("geodetic") / "mission.yaml",
                    test::readText(path("ned") / "mission.yaml") + yaml.str());
  }

  static double fscore(const std::string& run) {
    return test::evaluatedFscore(path("truth_world.ply"), path("visible_world.ply"),
                                 path(run) / "surface_points.ply");
  }

  static test::ScratchDir* dir_;
};

test::ScratchDir* BagNavSatFix::dir_ = nullptr;

TEST_F(BagNavSatFix, TheBagTwinReconstructsToTheSameFscoreWithTheCrs) {
  const double folder = fscore("geodetic.out");
  const double bag = fscore("twin.mcap.out");
  RecordProperty("fscore_folder", std::to_string(folder));
  RecordProperty("fscore_bag", std::to_string(bag));
  EXPECT_GT(folder, 0.7) << "a noise-free riser, 20 of its 98 frames";
  EXPECT_NEAR(bag, folder, kSameFscore);

  const auto report = nlohmann::json::parse(test::readText(path("twin.mcap.out") / "report.json"));
  EXPECT_EQ(report["crs"], kGrid);
  EXPECT_EQ(plyCrs(path("twin.mcap.out") / "surface_points.ply"), kGrid);
  EXPECT_NE(test::readText(path("twin.mcap.out") / "mesh.ply").find("comment crs EPSG:32631\n"),
            std::string::npos);
  // The origin is the first fix, on the grid, at depth 0.
  const Eigen::Vector3d origin = plyOrigin(path("twin.mcap.out") / "surface_points.ply");
  const NavSample first = readNavCsv(path("ned") / "nav.csv").samples().front();
  EXPECT_NEAR(origin.x(), kZeroEN.y() + first.position_m.x(), 1e-3);
  EXPECT_NEAR(origin.y(), kZeroEN.x() + first.position_m.y(), 1e-3);
  EXPECT_EQ(origin.z(), 0.0);

  const auto info = runCli("info " + quoted(path("twin.mcap")));
  ASSERT_EQ(info.exit_code, 0) << info.output;
  EXPECT_NE(info.output.find("sensor_msgs/msg/NavSatFix"), std::string::npos) << info.output;
  EXPECT_NE(info.output.find("position topic /gps/fix"), std::string::npos) << info.output;
  EXPECT_NE(info.output.find("EPSG:32631"), std::string::npos) << info.output;
}

}  // namespace
}  // namespace sonarcarve
