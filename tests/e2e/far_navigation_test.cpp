// Navigation far from zero, as survey navigation always is (issue 44): the same simulated riser
// with its navigation and ground truth moved to UTM-sized coordinates, 700 m and 10 km away,
// reconstructs to the same surface once its mission origin is added back, writes map.bt where
// the surface points are (or says clearly why it does not), and positions that make no
// physical sense are refused with the file and the place.
#include <gtest/gtest.h>

#include <octomap/OcTree.h>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "common/number_text.h"
#include "io/mesh/point_cloud_ply.h"
#include "io/mission/nav_csv.h"
#include "occlusion/surface_points.h"
#include "sonar/mission_origin.h"
#include "support/cli_runner.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

using test::quoted;
using test::runCli;

constexpr double kVoxel_m = 0.02;  // the default voxel size
// The bar of the issue: the same surface to a millimetre once the origin is added back.
constexpr double kSameSurface_m = 0.001;

// A PLY of the points (and faces) in world coordinates, written in double as a survey's files
// are: `points` + `offset_m`, to the nanometre.
void writeShiftedPly(const std::filesystem::path& path, const PlyMesh& mesh,
                     const Eigen::Vector3d& offset_m) {
  std::ostringstream out;
  out << "ply\nformat ascii 1.0\nelement vertex " << mesh.vertices.positions.size()
      << "\nproperty double x\nproperty double y\nproperty double z\n";
  if (!mesh.triangles.empty()) {
    out << "element face " << mesh.triangles.size() << "\nproperty list uchar int vertex_indices\n";
  }
  out << "end_header\n" << std::fixed;
  out.precision(9);
  for (const Eigen::Vector3f& p : mesh.vertices.positions) {
    const Eigen::Vector3d q = p.cast<double>() + offset_m;
    out << q.x() << ' ' << q.y() << ' ' << q.z() << '\n';
  }
  for (const auto& t : mesh.triangles) {
    out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  }
  test::writeText(path, out.str());
}

// A copy of `from` with its navigation, true poses and ground truth moved by `offset_m`.
void shiftMission(const std::filesystem::path& from, const std::filesystem::path& to,
                  const Eigen::Vector3d& offset_m) {
  std::filesystem::copy(from, to, std::filesystem::copy_options::recursive);
  for (const char* nav : {"nav.csv", "ground_truth_poses.csv"}) {
    test::writeText(to / nav, navCsvText(translatedTrack(readNavCsv(from / nav), offset_m)));
  }
  writeShiftedPly(to / "ground_truth.ply", readPlyMesh(from / "ground_truth.ply"), offset_m);
  writeShiftedPly(to / "visible_points.ply", {readPointCloudPly(from / "visible_points.ply"), {}},
                  offset_m);
}

nlohmann::json readReport(const std::filesystem::path& out) {
  return nlohmann::json::parse(test::readText(out / "report.json"));
}

// The riser, simulated once and reconstructed near zero, for every test of the file.
class FarNavigation : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::ScratchDir;
    const auto sim = runCli("simulate --scene riser --noise none --max-frames 20 --out " +
                            quoted(mission("near")));
    ASSERT_EQ(sim.exit_code, 0) << sim.output;
    const auto rec =
        runCli("reconstruct " + quoted(mission("near")) + " --out " + quoted(output("near")));
    ASSERT_EQ(rec.exit_code, 0) << rec.output;
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }
  static std::filesystem::path mission(const std::string& name) { return dir_->path() / name; }
  static std::filesystem::path output(const std::string& name) {
    return dir_->path() / ("out-" + name);
  }
  // The near mission moved by `offset_m` and reconstructed; the run's output.
  static test::RunResult reconstructShifted(const std::string& name,
                                            const Eigen::Vector3d& offset_m) {
    shiftMission(mission("near"), mission(name), offset_m);
    return runCli("reconstruct " + quoted(mission(name)) + " --out " + quoted(output(name)));
  }

  static test::ScratchDir* dir_;
};

test::ScratchDir* FarNavigation::dir_ = nullptr;

TEST_F(FarNavigation, UtmNavigationGivesTheSameSurfaceAsNearZero) {
  const Eigen::Vector3d utm(5'000'000.0, 500'000.0, 0.0);
  const auto rec = reconstructShifted("utm", utm);
  ASSERT_EQ(rec.exit_code, 0) << rec.output;

  const nlohmann::json near = readReport(output("near"));
  const nlohmann::json far = readReport(output("utm"));
  EXPECT_EQ(far["origin_ned_m"], nlohmann::json({5'000'000.0, 500'000.0, 0.0}));
  EXPECT_EQ(near["origin_ned_m"], nlohmann::json({0.0, 0.0, 0.0}));
  const SurfacePoints near_points = readSurfacePointsPly(output("near") / "surface_points.ply");
  ASSERT_GT(near_points.size(), 500u) << "the riser near zero should give hundreds of points";
  EXPECT_EQ(far["surface_points"], near_points.size());

  // World coordinates back, in double: every point where the near one is, plus the offset.
  const auto world_file = dir_->path() / "utm-world.ply";
  const auto exported =
      runCli("export " + quoted(output("utm")) +
             " --points --add-origin --format ply-ascii --out " + quoted(world_file));
  ASSERT_EQ(exported.exit_code, 0) << exported.output;
  EXPECT_NE(test::readText(world_file).find("property double x"), std::string::npos);
  const std::vector<Eigen::Vector3d> world = test::readAsciiPlyPoints(world_file);
  ASSERT_EQ(world.size(), near_points.size());
  double worst_m = 0.0;
  for (const Eigen::Vector3d& p : world) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const SurfacePoint& q : near_points) {
      nearest = std::min(nearest, (p - utm - q.position_m.cast<double>()).norm());
    }
    worst_m = std::max(worst_m, nearest);
  }
  EXPECT_LE(worst_m, kSameSurface_m) << "farthest UTM point from its near-zero twin";
  RecordProperty("worst_point_difference_mm", std::to_string(worst_m * 1e3));

  // The same accuracy: the ground truth moved alike and read into the same local frame. The
  // truth file holds its coordinates to the nanometre, so the figures agree to far below a
  // voxel; a point's share of the fractions is 1/1465.
  for (const char* block : {"evaluation", "mesh_evaluation"}) {
    ASSERT_TRUE(far.contains(block)) << block;
    for (const char* fraction : {"fscore", "precision", "completeness"}) {
      EXPECT_NEAR(far[block][fraction].get<double>(), near[block][fraction].get<double>(), 1e-3)
          << block << "." << fraction;
    }
    for (const char* distance : {"accuracy_mean_m", "accuracy_median_m", "accuracy_p90_m"}) {
      EXPECT_NEAR(far[block][distance].get<double>(), near[block][distance].get<double>(), 1e-6)
          << block << "." << distance;
    }
  }
  // evaluate, given the local points and the world ground truth, meets them in the local frame.
  const auto evaluated =
      runCli("evaluate --json --reference " + quoted(mission("utm") / "ground_truth.ply") +
             " --visible " + quoted(mission("utm") / "visible_points.ply") + " --reconstruction " +
             quoted(output("utm") / "surface_points.ply"));
  ASSERT_EQ(evaluated.exit_code, 0) << evaluated.output;
  const nlohmann::json figures = nlohmann::json::parse(evaluated.output);
  EXPECT_NEAR(figures["fscore"].get<double>(), near["evaluation"]["fscore"].get<double>(), 1e-3);
  RecordProperty("fscore_near", std::to_string(near["evaluation"]["fscore"].get<double>()));
  RecordProperty("fscore_utm", std::to_string(far["evaluation"]["fscore"].get<double>()));
}

// map.bt read back by OctoMap itself: its occupied voxels hold the surface points (local
// frame), and the file says which origin they are local to.
void expectMapBtWhereTheSurfaceIs(const std::filesystem::path& out, const Eigen::Vector3d& origin) {
  ASSERT_TRUE(std::filesystem::exists(out / "map.bt"));
  EXPECT_NE(test::readText(out / "map.bt").find("# origin_ned_m " + nedText(origin)),
            std::string::npos);
  octomap::OcTree tree((out / "map.bt").string());
  ASSERT_NEAR(tree.getResolution(), kVoxel_m, 1e-12);
  const SurfacePoints points = readSurfacePointsPly(out / "surface_points.ply");
  ASSERT_FALSE(points.empty());
  std::size_t occupied = 0;
  Eigen::AlignedBox3d surface, map;
  for (const SurfacePoint& p : points) {
    const octomap::OcTreeNode* node =
        tree.search(p.position_m.x(), p.position_m.y(), p.position_m.z());
    occupied += node != nullptr && tree.isNodeOccupied(node) ? 1 : 0;
    surface.extend(p.position_m.cast<double>());
  }
  for (auto it = tree.begin_leafs(); it != tree.end_leafs(); ++it) {
    if (tree.isNodeOccupied(*it)) {
      map.extend(Eigen::Vector3d(it.getX(), it.getY(), it.getZ()));
    }
  }
  // Every surface point is a first return: an occupied voxel on the shell, exported as such.
  EXPECT_EQ(occupied, points.size()) << "surface points in an occupied voxel of map.bt";
  // The occupied voxels lie around the surface (buried ones behind it are left out), not
  // 1310 m away as wrapped keys put them.
  EXPECT_LE((map.center() - surface.center()).norm(), 0.5);
}

TEST_F(FarNavigation, MapBtLiesWhereTheSurfacePointsAre700mAnd10kmAway) {
  for (const double north : {700.0, 10'000.0}) {
    SCOPED_TRACE(north);
    const std::string name = "north-" + shortestNumber(north);
    const auto rec = reconstructShifted(name, Eigen::Vector3d(north, 0.0, 0.0));
    ASSERT_EQ(rec.exit_code, 0) << rec.output;
    EXPECT_EQ(readReport(output(name))["origin_ned_m"], nlohmann::json({north, 0.0, 0.0}));
    expectMapBtWhereTheSurfaceIs(output(name), Eigen::Vector3d(north, 0.0, 0.0));
  }
}

TEST_F(FarNavigation, MapBeyondOctoMapKeysSkipsMapBtAndSaysWhy) {
  // The second half of the track 1400 m north of the first: the map spans more than OctoMap's
  // +-655.36 m at 2 cm voxels around any origin.
  const auto far = mission("split");
  std::filesystem::copy(mission("near"), far, std::filesystem::copy_options::recursive);
  std::vector<NavSample> samples = readNavCsv(mission("near") / "nav.csv").samples();
  for (std::size_t i = samples.size() / 2; i < samples.size(); ++i) {
    samples[i].position_m.x() += 1400.0;
  }
  test::writeText(far / "nav.csv", navCsvText(NavTrack(samples)));
  const auto rec = runCli("reconstruct " + quoted(far) + " --out " + quoted(output("split")));
  ASSERT_EQ(rec.exit_code, 0) << rec.output;
  EXPECT_NE(rec.output.find("map.bt: not written"), std::string::npos) << rec.output;
  EXPECT_NE(rec.output.find("655.36 m at 0.02 m voxels"), std::string::npos) << rec.output;
  EXPECT_FALSE(std::filesystem::exists(output("split") / "map.bt"));
  EXPECT_GT(readSurfacePointsPly(output("split") / "surface_points.ply").size(), 100u);
  bool warned = false;
  const nlohmann::json report = readReport(output("split"));
  for (const auto& choice : report["choices"]) {
    warned |= choice["name"] == "map.bt" && choice["warning"] == true;
  }
  EXPECT_TRUE(warned) << "report.json's choices should hold the map.bt warning";
}

TEST_F(FarNavigation, PositionsThatMakeNoSenseAreRefusedWithFileAndPlace) {
  // Navigation at 1e15 m: the line of nav.csv that holds it.
  const auto lost = mission("lost");
  std::filesystem::copy(mission("near"), lost, std::filesystem::copy_options::recursive);
  test::writeText(lost / "nav.csv",
                  navCsvText(translatedTrack(readNavCsv(mission("near") / "nav.csv"),
                                             Eigen::Vector3d(1e15, 0.0, 0.0))));
  const auto nav = runCli("reconstruct " + quoted(lost) + " --out " + quoted(output("lost")));
  EXPECT_NE(nav.exit_code, 0);
  EXPECT_LT(nav.exit_code, 128) << "a signal: " << nav.output;
  for (const char* fragment : {"nav.csv", "line 2", "within 1e8 m"}) {
    EXPECT_NE(nav.output.find(fragment), std::string::npos) << fragment << " in " << nav.output;
  }

  // A mounting 1e300 m from the vehicle: mission.yaml's key.
  const auto far_sonar = mission("far-sonar");
  std::filesystem::copy(mission("near"), far_sonar, std::filesystem::copy_options::recursive);
  std::string yaml = test::readText(far_sonar / "mission.yaml");
  const std::string mounting = "translation_m: [0.5, 0, 0.2]";
  ASSERT_NE(yaml.find(mounting), std::string::npos);
  yaml.replace(yaml.find(mounting), mounting.size(), "translation_m: [1e300, 0, 0.2]");
  test::writeText(far_sonar / "mission.yaml", yaml);
  const auto mount =
      runCli("reconstruct " + quoted(far_sonar) + " --out " + quoted(output("far-sonar")));
  EXPECT_NE(mount.exit_code, 0);
  EXPECT_LT(mount.exit_code, 128) << "a signal: " << mount.output;
  for (const char* fragment : {"mission.yaml", "mounting.translation_m", "within 1000 m"}) {
    EXPECT_NE(mount.output.find(fragment), std::string::npos) << fragment << " in " << mount.output;
  }
}

}  // namespace
}  // namespace sonarcarve
