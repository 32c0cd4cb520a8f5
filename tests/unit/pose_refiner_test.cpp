// Robust carving (CarveParams::carve_votes) and pose refinement (PoseRefiner) in the fast
// engine: a frame placed off its true pose is pulled back onto the map, never beyond the
// search window, and turning both off changes nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "carve/carver.h"
#include "carve/fast_carver.h"
#include "carve/pose_refiner.h"
#include "carve/voxel_map.h"
#include "common/angles.h"
#include "sim/demo_scenes.h"
#include "sim/ray_caster.h"
#include "sim/sonar_simulator.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

constexpr double kVoxel = CarveParams::kDefaultVoxelSize_m;
// Residuals are capped beyond the largest displacement tried (1 degree: 8 cm at the riser).
constexpr double kScale = 0.1;

// Views of the riser demo scene's module and tie-backs (14 to 15.5 m deep): a level sonar
// 4.5 m south of the riser's axis, stepping down 10 cm a frame, as the paper's inspection.
class PoseRefinement : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    scene_ = new Scene(makeDemoScene("riser"));
    caster_ = new RayCaster(*scene_);
    sonar_ = new SonarModel(test::paperSonar());
    pool_ = new ThreadPool(2);
    const SonarSimulator simulator(*caster_, *sonar_, test::clippedBeam(), *pool_);
    images_ = new std::vector<cv::Mat>();
    for (int i = 0; i < kFrames; ++i) {
      images_->push_back(simulator.render(truePose(i)));
    }
  }
  static void TearDownTestSuite() {
    delete images_;
    delete pool_;
    delete sonar_;
    delete caster_;
    delete scene_;
  }

  static constexpr int kFrames = 30;
  static constexpr int kHeldOut = 20;  // the frame refined: not carved into the map

  static Eigen::Isometry3d truePose(int i) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.translation() = Eigen::Vector3d(-4.5, 0.0, 12.5 + 0.1 * i);
    return T;
  }

  static CarveParams params() {
    CarveParams p;
    p.beam_aware = false;  // the frames are rendered with the clipped beam: the paper's rule
    p.region =
        Eigen::AlignedBox3d(Eigen::Vector3d(-1.5, -3.0, 11.0), Eigen::Vector3d(1.5, 3.0, 17.5));
    return p;
  }

  // Every frame but the held-out one carved at its true pose, with only its returns over
  // `level` (as the pipeline carves its alignment maps behind a detector).
  static void carveAllButHeldOut(VoxelMap& map, const CarveParams& p, float level = 0.0f) {
    FastCarver carver(map, *sonar_, p, *pool_);
    for (int i = 0; i < kFrames; ++i) {
      if (i != kHeldOut) {
        const cv::Mat& frame = (*images_)[static_cast<std::size_t>(i)];
        cv::Mat over = frame.clone();
        over.setTo(0.0f, frame <= level);
        carver.integrate(over, truePose(i), static_cast<std::uint32_t>(i + 1));
      }
    }
  }

  static Scene* scene_;
  static RayCaster* caster_;
  static SonarModel* sonar_;
  static ThreadPool* pool_;
  static std::vector<cv::Mat>* images_;
};
Scene* PoseRefinement::scene_ = nullptr;
RayCaster* PoseRefinement::caster_ = nullptr;
SonarModel* PoseRefinement::sonar_ = nullptr;
ThreadPool* PoseRefinement::pool_ = nullptr;
std::vector<cv::Mat>* PoseRefinement::images_ = nullptr;

Eigen::Isometry3d displaced(const Eigen::Isometry3d& T, const Eigen::Vector3d& shift_world,
                            double yaw_rad) {
  Eigen::Isometry3d out = T;
  out.translation() += shift_world;
  out.linear() = T.linear() * Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()).matrix();
  return out;
}

TEST_F(PoseRefinement, AFrameDisplacedByAKnownOffsetIsPulledBackToWithinAVoxel) {
  const CarveParams p = params();
  VoxelMap map(p.voxel_size_m, *p.region);
  carveAllButHeldOut(map, p);
  const PoseRefiner refiner(map, *sonar_, p, PoseRefinementParams{}, *pool_);
  const Eigen::Isometry3d truth = truePose(kHeldOut);
  const cv::Mat& image = (*images_)[kHeldOut];
  struct Offset {
    Eigen::Vector3d shift;
    double yaw_deg;
  };
  // Towards the riser, away from it, sideways, and turned: each several voxels.
  for (const Offset& o : {Offset{{0.06, 0.0, 0.0}, 0.0}, Offset{{-0.06, 0.0, 0.0}, 0.0},
                          Offset{{0.0, 0.06, 0.0}, 0.0}, Offset{{0.0, 0.0, 0.0}, 1.0},
                          Offset{{0.04, -0.04, 0.0}, -0.5}}) {
    const Eigen::Isometry3d prior = displaced(truth, o.shift, degToRad(o.yaw_deg));
    const PoseCorrection c = refiner.measure(image, prior, Vector6d::Zero(), kScale).correction;
    ASSERT_TRUE(c.aligned) << "shell voxels in view: " << c.voxels << ", agreement "
                           << c.score_after;
    const Eigen::Isometry3d refined = c.applied(prior);
    // Where the refined pose puts the riser's near face (4.5 m ahead) against the truth: a
    // turn moves it by its arc there.
    const Eigen::Vector3d ahead(4.1, 0.0, 0.0);
    const double error = (refined * ahead - truth * ahead).norm();
    EXPECT_LT(error, kVoxel) << "offset " << o.shift.transpose() << " m, " << o.yaw_deg
                             << " deg: off by " << error << " m after refinement, "
                             << (prior * ahead - truth * ahead).norm() << " m before";
    EXPECT_GT(c.score_after, c.score_before);
  }
}

TEST_F(PoseRefinement, TheRefinedPoseNeverLeavesTheSearchWindow) {
  const CarveParams p = params();
  VoxelMap map(p.voxel_size_m, *p.region);
  carveAllButHeldOut(map, p);
  PoseRefinementParams window;
  window.max_translation_m = 0.03;
  window.max_rotation_rad = degToRad(0.2);
  const PoseRefiner refiner(map, *sonar_, p, window, *pool_);
  // Off by more than the window: the best pose lies outside it, so the search stops at its
  // edge (close enough to the truth to agree with the frame).
  const Eigen::Isometry3d prior = displaced(truePose(kHeldOut), {0.05, 0.0, 0.0}, degToRad(0.3));
  Vector6d outside;  // a start outside the window is brought in
  outside << 0.2, -0.2, 0.0, 0.0, 0.0, degToRad(3.0);
  for (const Vector6d& start : {Vector6d(Vector6d::Zero()), outside}) {
    const PoseCorrection c = refiner.measure((*images_)[kHeldOut], prior, start, kScale).correction;
    for (int a = 0; a < 3; ++a) {
      EXPECT_LE(std::abs(c.translation_world_m[a]), window.max_translation_m + 1e-12);
      EXPECT_LE(std::abs(c.rotation_sonar_rad[a]), window.max_rotation_rad + 1e-12);
    }
    EXPECT_TRUE(c.aligned);
    EXPECT_GT(c.translation_world_m.norm(), 0.5 * window.max_translation_m)
        << "it should have moved towards the truth";
  }
}

// Behind a detector some background gets through: runs of two bins that begin a return in
// most beams, nearer than the structure. The edge level keeps them from beginning edges.
TEST_F(PoseRefinement, BehindADetectorReturnsUnderTheEdgeLevelBeginNoEdges) {
  cv::Mat image = (*images_)[kHeldOut].clone();
  std::vector<float> lit;
  for (auto it = image.begin<float>(); it != image.end<float>(); ++it) {
    if (*it > 0.0f) {
      lit.push_back(*it);
    }
  }
  ASSERT_FALSE(lit.empty());
  std::nth_element(lit.begin(), lit.begin() + lit.size() / 100, lit.end());
  // Under all but a hundredth of the riser's returns, and twice what the leaks read.
  const float level = lit[lit.size() / 100];
  const CarveParams p = params();
  VoxelMap map(p.voxel_size_m, *p.region);
  carveAllButHeldOut(map, p, level);
  const int near_row = static_cast<int>(2.0 / sonar_->range().resolution_m);
  for (int beam = 0; beam < image.cols; beam += 2) {
    const int row = near_row + (beam * 7) % 60;
    image.at<float>(row, beam) = 0.5f * level;
    image.at<float>(row + 1, beam) = 0.5f * level;
  }
  const Eigen::Isometry3d truth = truePose(kHeldOut);
  const Eigen::Isometry3d prior = displaced(truth, {0.06, 0.0, 0.0}, 0.0);
  const Eigen::Vector3d ahead(4.1, 0.0, 0.0);
  PoseRefiner refiner(map, *sonar_, p, PoseRefinementParams{}, *pool_);
  const PoseCorrection blind = refiner.measure(image, prior, Vector6d::Zero(), kScale).correction;
  // Without a level the leaks begin edges in beams where the map predicts none: each costs the
  // cap whatever the pose, and the frame agrees with the map in few of its beams.
  refiner.setEdgeLevel(cv::Mat(image.size(), CV_32F, cv::Scalar(level)));
  const PoseCorrection c = refiner.measure(image, prior, Vector6d::Zero(), kScale).correction;
  EXPECT_LT((c.applied(prior) * ahead - truth * ahead).norm(), kVoxel);
  EXPECT_GT(c.score_after, blind.score_after + 0.5)
      << "with the level " << c.score_after << ", without " << blind.score_after;
}

// Behind a detector only voxels that enough frames see predict edges.
TEST_F(PoseRefinement, VoxelsSeenByFewerFramesThanMinViewsPredictNothing) {
  const CarveParams p = params();
  VoxelMap map(p.voxel_size_m, *p.region);
  carveAllButHeldOut(map, p);
  PoseRefiner refiner(map, *sonar_, p, PoseRefinementParams{}, *pool_);
  const std::size_t all = refiner.shellVoxels();
  std::vector<Eigen::Isometry3d> poses;
  for (int i = 0; i < kFrames; ++i) {
    poses.push_back(truePose(i));
  }
  PoseRefiner seen_by_all(map, *sonar_, p, PoseRefinementParams{}, *pool_);
  seen_by_all.keepVoxelsSeenBy(poses);
  EXPECT_GT(seen_by_all.shellVoxels(), 0u);
  EXPECT_LE(seen_by_all.shellVoxels(), all);
  // Four frames: no voxel is inside five frames' apertures.
  poses.resize(PoseRefinementParams{}.min_views - 1);
  refiner.keepVoxelsSeenBy(poses);
  EXPECT_EQ(refiner.shellVoxels(), 0u);
}

TEST_F(PoseRefinement, WithTooFewVoxelsInViewAFrameGivesNoMeasurement) {
  const CarveParams p = params();
  VoxelMap map(p.voxel_size_m, *p.region);  // nothing carved
  const PoseRefiner refiner(map, *sonar_, p, PoseRefinementParams{}, *pool_);
  const PoseMeasurement m = refiner.measure((*images_)[0], truePose(0), Vector6d::Zero(), kScale);
  const PoseCorrection& c = m.correction;
  EXPECT_FALSE(c.aligned);
  EXPECT_EQ(m.information, Matrix6d::Zero());
  EXPECT_EQ(c.translation_world_m, Eigen::Vector3d::Zero());
  EXPECT_EQ(c.rotation_sonar_rad, Eigen::Vector3d::Zero());
}

// Robust carving: a voxel found empty by fewer views than carve_votes is not carved; more
// votes never carve what fewer keep, and the values of voxels both keep are the same minimum.
// (One vote is the seed paper's rule: carve_agreement_test holds it to the reference engine.)
TEST_F(PoseRefinement, MoreCarveVotesCarveLessAndNeverWhatFewerKeep) {
  CarveParams one = params();
  CarveParams three = params();
  three.carve_votes = 3;
  VoxelMap map_one(one.voxel_size_m, *one.region, keepsViewCounts(one));
  VoxelMap map_three(three.voxel_size_m, *three.region, keepsViewCounts(three));
  carveAllButHeldOut(map_one, one);
  carveAllButHeldOut(map_three, three);
  std::size_t carved_one = 0, carved_three = 0, kept_by_votes = 0;
  for (std::size_t b = 0; b < map_one.blockCount(); ++b) {
    for (int i = 0; i < VoxelMap::kBlockVoxels; ++i) {
      const Eigen::Vector3i v = map_one.voxelIndex(b, i);
      const float a = map_one.value(v);
      const float c = map_three.value(v);
      carved_one += a == 0.0f ? 1 : 0;
      carved_three += c == 0.0f ? 1 : 0;
      kept_by_votes += (a == 0.0f && c > 0.0f && c < VoxelMap::kUnknown) ? 1 : 0;
      if (c == 0.0f) {
        ASSERT_EQ(a, 0.0f) << "three votes carved what one did not";
      }
      if (a > 0.0f && a < VoxelMap::kUnknown) {
        ASSERT_EQ(a, c) << "a voxel that no view found empty keeps its minimum";
      }
    }
  }
  EXPECT_LT(carved_three, carved_one);
  EXPECT_GT(kept_by_votes, 0u);
}

}  // namespace
}  // namespace sonarcarve
