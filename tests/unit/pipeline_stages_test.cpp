// The pipeline's stages one by one, on a tiny sonar and a hand-made recording: frame
// selection and placement, carving with broken frames and cancellation, the map's bounds,
// occlusion resolution with its view count, and the mesh stage's lower limit.
#include <gtest/gtest.h>

#include <array>

#include "carve/voxel_map.h"
#include "common/angles.h"
#include "common/error.h"
#include "io/frame_source.h"
#include "pipeline/carve_stage.h"
#include "pipeline/frame_stage.h"
#include "pipeline/reconstruction.h"
#include "pipeline/surface_stage.h"

namespace sonarcarve {
namespace {

SonarModel tinySonar() {
  return SonarModel("tiny", RangeBins{1.0, 0.04, 50}, BearingTable::uniform(degToRad(20), 20),
                    degToRad(10));
}

// Frames lit at 2 m; the frames listed in `broken` fail to load.
class RingSource final : public FrameSource {
 public:
  RingSource(std::size_t frames, std::vector<std::size_t> broken)
      : frames_(frames), broken_(std::move(broken)) {}
  std::string kind() const override { return "rings"; }
  std::size_t size() const override { return frames_; }
  Frame load(std::size_t index) const override {
    if (std::find(broken_.begin(), broken_.end(), index) != broken_.end()) {
      throw Error("rings", "frame " + std::to_string(index), "broken on purpose");
    }
    const SonarModel sonar = tinySonar();
    Frame frame{0.0, sonar.id(), cv::Mat(sonar.rows(), sonar.cols(), CV_32F, cv::Scalar(0.0f))};
    frame.image.row(*sonar.range().binOf(2.01)).setTo(100.0f);
    return frame;
  }

 private:
  std::size_t frames_;
  std::vector<std::size_t> broken_;
};

// A vertical dive of `frames` frames, one a second, 5 cm apart; navigation over [0, nav_end].
Mission ringMission(std::size_t frames, std::vector<std::size_t> broken = {},
                    double nav_end_s = 1e3) {
  std::vector<NavSample> samples(2);
  samples[1].time_s = nav_end_s;
  samples[1].position_m.z() = 0.05 * nav_end_s;
  Mission mission{"rings",
                  "rings",
                  tinySonar(),
                  Mounting{},
                  NavTrack(samples),
                  {},
                  "",
                  "",
                  std::make_shared<RingSource>(frames, std::move(broken)),
                  {},
                  {}};
  for (std::size_t i = 0; i < frames; ++i) {
    mission.frames.push_back({static_cast<double>(i), "tiny", "frame", 0});
  }
  return mission;
}

struct Skipped {
  std::vector<FrameProblem> problems;
  std::function<void(const FrameProblem&)> sink() {
    return [this](const FrameProblem& p) { problems.push_back(p); };
  }
};

TEST(FrameStage, SelectsFirstLastAndStride) {
  EXPECT_EQ(selectFrames(10, {}), (std::vector<std::size_t>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9}));
  EXPECT_EQ(selectFrames(10, {2, 8, 3}), (std::vector<std::size_t>{2, 5}));
  EXPECT_EQ(selectFrames(10, {7, 100, 1}), (std::vector<std::size_t>{7, 8, 9}));
  EXPECT_TRUE(selectFrames(10, {12, -1, 1}).empty());
}

TEST(FrameStage, FramesOutsideTheNavigationAreSkippedWithTheirTime) {
  const Mission mission = ringMission(10, {}, 6.5);  // frames 7, 8, 9 after the track ends
  Skipped skipped;
  const auto posed = placeFrames(mission, {}, skipped.sink());
  ASSERT_EQ(posed.size(), 7u);
  EXPECT_NEAR(posed[4].T_world_sonar.translation().z(), 0.2, 1e-12);  // 4 s at 5 cm/s
  ASSERT_EQ(skipped.problems.size(), 3u);
  EXPECT_EQ(skipped.problems.front().index, 7u);
  EXPECT_NE(skipped.problems.front().message.find("outside the navigation"), std::string::npos);
}

TEST(FrameStage, PlacedFramesAreTheSelectedOnesTheNavigationCovers) {
  const Mission mission = ringMission(10, {}, 6.5);  // frames 7, 8, 9 after the track ends
  ReconstructionParams params;
  params.stride = 2;
  EXPECT_EQ(placedFrames(mission, params), (std::vector<std::size_t>{0, 2, 4, 6}));
  params.first_frame = 7;
  params.stride = 1;
  EXPECT_TRUE(placedFrames(mission, params).empty());
}

class CarveStageTest : public ::testing::Test {
 protected:
  CarveStageResult carve(const Mission& mission, Progress& progress, Skipped& skipped,
                         CarveStageParams params = {}) {
    const auto posed = placeFrames(mission, {}, skipped.sink());
    NoiseChoice none;
    none.detector = detector_;
    const DenoisedFrames frames(mission, mission.sonar, none);
    const CarveStage stage(mission.sonar, params, pool_);
    return stage.run(posed, stage.mapBounds(posed), frames, progress, nullptr, skipped.sink());
  }
  DetectorParams detector_ = [] {
    DetectorParams d;
    d.mode = DetectorMode::None;
    return d;
  }();
  ThreadPool pool_{2};
};

TEST_F(CarveStageTest, ABrokenFrameIsSkippedAndTheOthersCarved) {
  const Mission mission = ringMission(8, {3, 5});
  Skipped skipped;
  SilentProgress progress;
  const CarveStageResult r = carve(mission, progress, skipped);
  EXPECT_EQ(r.used.size(), 6u);
  EXPECT_EQ(r.carve_ms.size(), 6u);
  ASSERT_EQ(skipped.problems.size(), 2u);
  EXPECT_EQ(skipped.problems[0].index, 3u);
  EXPECT_NE(skipped.problems[1].message.find("broken on purpose"), std::string::npos);
  EXPECT_GT(r.carver->stats().occupied_voxels, 0u);
  ASSERT_TRUE(r.carve.region);  // the map's bounds, as used
}

TEST_F(CarveStageTest, WithPoseRefinementOffFramesCarveExactlyAtTheirNavigationPoses) {
  // Refinement off (the default) is the carving of before: the same frames carved by hand at
  // the navigation's poses give the same map, voxel for voxel.
  const Mission mission = ringMission(8);
  Skipped skipped;
  SilentProgress progress;
  const CarveStageResult r = carve(mission, progress, skipped);
  EXPECT_TRUE(r.refinement.empty());
  const auto posed = placeFrames(mission, {}, skipped.sink());
  NoiseChoice none;
  none.detector = detector_;
  const DenoisedFrames frames(mission, mission.sonar, none);
  auto by_hand = makeCarver(CarverEngine::Fast, CarverSetup{mission.sonar, r.carve, pool_});
  for (std::size_t n = 0; n < posed.size(); ++n) {
    by_hand->integrate(frames.load(posed[n].index).image, posed[n].T_world_sonar,
                       static_cast<std::uint32_t>(n + 1));
  }
  const VoxelMap* a = r.carver->blockMap();
  const VoxelMap* b = by_hand->blockMap();
  if (a == nullptr || b == nullptr) {
    FAIL() << "the fast engine keeps a block map";
  }
  ASSERT_EQ(a->blockCount(), b->blockCount());
  std::array<float, VoxelMap::kBlockVoxels> va{}, vb{};
  for (std::size_t block = 0; block < a->blockCount(); ++block) {
    a->copyValues(block, va.data());
    b->copyValues(block, vb.data());
    ASSERT_EQ(va, vb) << "block " << block;
  }
  EXPECT_GT(a->occupiedCount(), 0u);
}

// An evicting run (pipeline/evicting_surface.h) hears of each carved frame before the memory
// budget's check, so the check sees the map after its finished pages have gone.
TEST_F(CarveStageTest, TheBudgetCheckSeesTheMapAfterEachFramesEviction) {
  const Mission mission = ringMission(8, {3, 5});
  Skipped skipped;
  SilentProgress progress;
  const auto posed = placeFrames(mission, {}, skipped.sink());
  NoiseChoice none;
  none.detector = detector_;
  const DenoisedFrames frames(mission, mission.sonar, none);
  const CarveStage stage(mission.sonar, {}, pool_);
  std::vector<std::size_t> positions, started;
  std::size_t held_bytes = 0, left_bytes = 0;
  CarveHooks hooks;
  hooks.starting = [&](std::size_t position, Carver&) { started.push_back(position); };
  hooks.carved = [&](std::size_t position, const Eigen::Isometry3d&, Carver& carver) {
    positions.push_back(position);
    VoxelMap* map = carver.evictableMap();
    if (map == nullptr) {
      ADD_FAILURE() << "the fast engine's map can be evicted";
      return;
    }
    held_bytes = map->memoryBytes();
    for (std::size_t page = 0; page < map->pageCount(); ++page) {
      map->releasePage(page);
    }
    left_bytes = map->memoryBytes();
  };
  std::size_t checks = 0;
  const CarvedFrameCheck check = [&](const CarvedSoFar& at) {
    ++checks;
    EXPECT_EQ(at.map_bytes, static_cast<double>(left_bytes));
    EXPECT_LT(left_bytes, held_bytes);  // each frame's pages were there, and went
  };
  stage.run(posed, stage.mapBounds(posed), frames, progress, nullptr, skipped.sink(), check, hooks);
  // Every frame is heard of before it is loaded; frames that failed to load are not reported
  // as carved: their place in the order is skipped.
  EXPECT_EQ(started, (std::vector<std::size_t>{0, 1, 2, 3, 4, 5, 6, 7}));
  EXPECT_EQ(positions, (std::vector<std::size_t>{0, 1, 2, 4, 6, 7}));
  EXPECT_EQ(checks, 6u);
}

class StopAfter final : public Progress {
 public:
  explicit StopAfter(std::size_t reports) : left_(reports) {}
  void report(const std::string&, std::size_t, std::size_t) override {
    left_ = left_ > 0 ? left_ - 1 : 0;
  }
  bool cancelled() const override { return left_ == 0; }

 private:
  std::size_t left_;
};

TEST_F(CarveStageTest, CancellationStopsBetweenFrames) {
  const Mission mission = ringMission(10);
  Skipped skipped;
  StopAfter progress(4);
  const CarveStageResult r = carve(mission, progress, skipped);
  EXPECT_TRUE(r.cancelled);
  EXPECT_EQ(r.used.size(), 4u);
}

TEST_F(CarveStageTest, ARegionOutsideEveryViewIsAnErrorNamingTheRegion) {
  const Mission mission = ringMission(4);
  Skipped skipped;
  CarveStageParams params;
  params.carve.region =
      Eigen::AlignedBox3d(Eigen::Vector3d(50, 50, 50), Eigen::Vector3d(51, 51, 51));
  const auto posed = placeFrames(mission, {}, skipped.sink());
  try {
    CarveStage(mission.sonar, params, pool_).mapBounds(posed);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.place(), "region");
  }
}

TEST_F(CarveStageTest, OcclusionKeepsVoxelsSeenAsFirstReturnInEnoughViews) {
  const Mission mission = ringMission(12);
  Skipped skipped;
  SilentProgress progress;
  const CarveStageResult r = carve(mission, progress, skipped);
  const auto few = resolveSurface(*r.carver, r.used, mission.sonar, r.carve, 1, pool_, progress);
  const auto many = resolveSurface(*r.carver, r.used, mission.sonar, r.carve, 6, pool_, progress);
  ASSERT_FALSE(many.surface.empty());
  EXPECT_LT(many.surface.size(), few.surface.size());
  for (const SurfacePoint& p : many.surface) {
    EXPECT_GE(p.views, 6u);
  }
  EXPECT_FALSE(many.cancelled);
}

TEST(MeshStage, TooFewPointsGiveNoMesh) {
  SilentProgress progress;
  SurfacePoints nine(9, SurfacePoint{Eigen::Vector3f::Zero(), 1.0f, 1});
  EXPECT_TRUE(meshStage(nine, MeshParams{}, 0.02, progress).triangles.empty());
}

}  // namespace
}  // namespace sonarcarve
