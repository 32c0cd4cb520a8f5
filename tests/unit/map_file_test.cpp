// The carved map on disk and the fusion of maps (carve/map_file.h): merging the maps of two
// halves of a mission gives the map of the whole, voxel by voxel; a saved map reads back the
// same; broken files are refused naming the byte.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>

#include "carve/carving_geometry.h"
#include "carve/fast_carver.h"
#include "carve/map_file.h"
#include "common/angles.h"
#include "sim/demo_scenes.h"
#include "sim/ray_caster.h"
#include "sim/sonar_simulator.h"
#include "sim/trajectory.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

constexpr std::size_t kFrames = 12;

// Twelve frames of the riser's vertical inspection on the realistic beam, carved beam-aware
// with one keep level, into a whole-mission map and into the maps of its two halves, each over
// the box its own frames see (as a run of each would).
class MapFusion : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const Scene riser = makeDemoScene("riser");
    const RayCaster caster(riser);
    ImagingSettings imaging;  // the realistic beam, coarser rays to keep the test quick
    imaging.elevation_step_rad = degToRad(0.25);
    imaging.rays_per_beam = 1;
    ThreadPool pool(2);
    const SonarModel sonar = test::paperSonar();
    const SonarSimulator simulator(caster, sonar, imaging, pool);
    const Trajectory trajectory = makeTrajectory(TrajectorySpec{}, riser.target);
    CarveParams params;
    params.keep_level = 100.0;
    params.dark_pixels = CarveParams::DarkPixels::Exact;
    const CarvingGeometry geometry(sonar, params);
    std::vector<Eigen::Isometry3d> poses;
    std::vector<cv::Mat> images;
    for (std::size_t i = 0; i < kFrames; ++i) {
      poses.push_back(trajectory.T_world_sonar(20 + 2 * i));  // along the buoyancy modules
      images.push_back(simulator.render(poses.back()));
    }
    const auto carve = [&](std::size_t from, std::size_t to) {
      Eigen::AlignedBox3d box;
      for (std::size_t i = from; i < to; ++i) {
        box.extend(geometry.frustumBounds(poses[i]));
      }
      auto map = std::make_unique<VoxelMap>(params.voxel_size_m, box);
      FastCarver carver(*map, sonar, params, pool);
      for (std::size_t i = from; i < to; ++i) {
        carver.integrate(images[i], poses[i], static_cast<std::uint32_t>(i + 1));
      }
      return map;
    };
    whole_ = carve(0, kFrames).release();
    first_half_ = carve(0, kFrames / 2).release();
    second_half_ = carve(kFrames / 2, kFrames).release();
  }
  static void TearDownTestSuite() {
    delete whole_;
    delete first_half_;
    delete second_half_;
  }
  static VoxelMap* whole_;
  static VoxelMap* first_half_;
  static VoxelMap* second_half_;
};
VoxelMap* MapFusion::whole_ = nullptr;
VoxelMap* MapFusion::first_half_ = nullptr;
VoxelMap* MapFusion::second_half_ = nullptr;

TEST_F(MapFusion, MergingTheHalvesGivesTheWholeMissionVoxelByVoxel) {
  // Not a trivial case: each half observed voxels the other did not, and carved some the
  // other kept.
  ASSERT_FALSE(sameVoxels(*first_half_, *whole_));
  ASSERT_FALSE(sameVoxels(*second_half_, *whole_));
  ASSERT_GT(whole_->occupiedCount(), 10000u);
  const auto merged = mergeMaps(*first_half_, *second_half_);
  EXPECT_TRUE(sameVoxels(*merged, *whole_));
  EXPECT_EQ(merged->occupiedCount(), whole_->occupiedCount());
  // In either order.
  EXPECT_TRUE(sameVoxels(*mergeMaps(*second_half_, *first_half_), *whole_));
}

TEST_F(MapFusion, ASavedMapReadsBackTheSame) {
  test::ScratchDir dir;
  const auto path = dir.path() / "whole.scmap";
  saveMap(*whole_, path);
  const auto loaded = loadMap(path);
  EXPECT_TRUE(sameVoxels(*loaded, *whole_));
  EXPECT_EQ(loaded->firstBlock(), whole_->firstBlock());
  EXPECT_EQ(loaded->blockDims(), whole_->blockDims());
  EXPECT_EQ(loaded->blockCount(VoxelMap::BlockState::Free),
            whole_->blockCount(VoxelMap::BlockState::Free));
  // Saving the loaded map again gives the same bytes.
  saveMap(*loaded, dir.path() / "again.scmap");
  EXPECT_EQ(test::readText(path), test::readText(dir.path() / "again.scmap"));
}

TEST(MapFile, MapsOfOtherVoxelSizesDoNotMerge) {
  const Eigen::AlignedBox3d box(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  test::expectError([&] { mergeMaps(VoxelMap(0.02, box), VoxelMap(0.05, box)); },
                    {"merge", "0.02", "0.05", "expected one grid"});
}

// A small map with every kind of block, saved to bytes.
std::string smallMapBytes(const std::filesystem::path& dir) {
  VoxelMap map(0.1, Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(1, 1, 1)));
  std::vector<float> values(VoxelMap::kBlockVoxels, 5.0f);
  values[3] = 0.0f;
  values[7] = VoxelMap::kUnknown;
  map.storeBlock(0, values.data(), 1);
  map.storeBlock(2, nullptr, 1);
  saveMap(map, dir / "small.scmap");
  return test::readText(dir / "small.scmap");
}

void writeBytes(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

TEST(MapFile, BrokenFilesAreRefusedNamingTheByte) {
  test::ScratchDir dir;
  const std::string good = smallMapBytes(dir.path());
  const auto bad = dir.path() / "bad.scmap";
  // Header: magic 8, version 4, voxel size 8, first block 12, dims 12, block count 8 = 52;
  // then block 0 (index 8, state 1, 2048 values), block 2 (index 8, state 1), end marker 8.
  ASSERT_EQ(good.size(), 52u + 8 + 1 + 2048 + 8 + 1 + 8);
  // Every message names the file first.
  const auto refused = [&](const std::string& bytes, const std::vector<std::string>& fragments) {
    writeBytes(bad, bytes);
    test::expectError([&] { loadMap(bad); }, fragments);
    test::expectError([&] { loadMap(bad); }, {"bad.scmap"});
  };
  refused("", {"byte 0", "empty"});
  refused("PK\x03\x04 a zip file", {"byte 0", "not a SonarCarve map file"});
  // Cut anywhere: the header, a block's values, before the end marker.
  for (const std::size_t cut : std::vector<std::size_t>{10, 40, 60, 1000, good.size() - 4}) {
    refused(good.substr(0, cut), {"the file ends", "cut short"});
  }
  std::string version = good;
  version[8] = 7;
  refused(version, {"byte 8", "format version 7"});
  std::string state = good;
  state[52 + 8] = 9;
  refused(state, {"byte 60", "block state 9"});
  std::string nan = good;
  const float not_a_number = std::nanf("");
  std::memcpy(&nan[52 + 9 + 4 * 10], &not_a_number, 4);
  refused(nan, {"byte 101", "voxel value", "expected 0 (carved)"});
  std::string order = good;
  order[52 + 9 + 2048] = 0;  // the second block's index, 2, made 0: not increasing
  refused(order, {"byte 2109", "block index 0", "increasing"});
  refused(good + "x", {"1 bytes after the end marker"});
  writeBytes(bad, good);
  EXPECT_NO_THROW(loadMap(bad));
  test::expectError([&] { loadMap(dir.path() / "missing.scmap"); }, {"not found"});
}

}  // namespace
}  // namespace sonarcarve
