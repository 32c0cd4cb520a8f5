// The behaviour every carving engine must have, run over every registered engine (the
// built-in ones and any a test registers): the minimum over views, unknown versus carved,
// carved stays carved, the sign of elevation, the intensity threshold, surface candidates.
#include <gtest/gtest.h>

#include <set>
#include <tuple>

#include "carve/carver.h"
#include "carve/voxel_map.h"
#include "common/angles.h"
#include "common/error.h"

namespace sonarcarve {
namespace {

// A narrow sonar: 4 cm bins from 1 m to 3 m, 5 beams over 10 degrees, 10 degree aperture.
// Its beam is clipped, the seed paper's model, under which every engine carves by the paper's
// rule (beam-aware carving of a real beam: beam_aware_carving_test.cpp).
SonarModel tinySonar() {
  return SonarModel("tiny", RangeBins{1.0, 0.04, 50}, BearingTable::uniform(degToRad(10), 5),
                    degToRad(10))
      .withElevationBeam(ElevationBeam::Clipped);
}

// An image lit with `value` in the bin around `range_m` in every beam, dark elsewhere.
cv::Mat ringImage(const SonarModel& sonar, double range_m, float value) {
  cv::Mat image(sonar.rows(), sonar.cols(), CV_32F, cv::Scalar(0.0f));
  if (const auto bin = sonar.range().binOf(range_m)) {
    image.row(*bin).setTo(value);
  }
  return image;
}

Eigen::Isometry3d sonarAt(double down_m, double pitch_rad = 0.0) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(pitch_rad, Eigen::Vector3d::UnitY()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(0, 0, down_m);
  return T;
}

class CarverBehaviour : public ::testing::TestWithParam<CarverEngine> {
 protected:
  std::unique_ptr<Carver> make(CarveParams params = {}) {
    params.region =
        Eigen::AlignedBox3d(Eigen::Vector3d(0.5, -0.5, -0.5), Eigen::Vector3d(3.5, 0.5, 0.5));
    return makeCarver(GetParam(), CarverSetup{sonar_, params, pool_});
  }
  void view(Carver& carver, const cv::Mat& image, const Eigen::Isometry3d& T) {
    carver.integrate(image, T, ++stamp_);
  }
  static float valueAt(const Carver& carver, const Eigen::Vector3d& p) {
    const Eigen::Vector3i voxel =
        (p / CarveParams::kDefaultVoxelSize_m).array().floor().cast<int>();
    return carver.value(voxel);
  }

  SonarModel sonar_ = tinySonar();
  ThreadPool pool_{2};
  std::uint32_t stamp_ = 0;
};

TEST_P(CarverBehaviour, EachVoxelKeepsTheMinimumOverViews) {
  auto carver = make();
  const Eigen::Vector3d target(2.01, 0.0, 0.0);  // on the boresight, inside bin 25
  view(*carver, ringImage(sonar_, 2.01, 50.0f), sonarAt(0.0));
  EXPECT_EQ(valueAt(*carver, target), 50.0f);
  view(*carver, ringImage(sonar_, 2.01, 30.0f), sonarAt(0.0));
  EXPECT_EQ(valueAt(*carver, target), 30.0f);
  view(*carver, ringImage(sonar_, 2.01, 80.0f), sonarAt(0.0));
  EXPECT_EQ(valueAt(*carver, target), 30.0f);  // a brighter view does not raise it
}

TEST_P(CarverBehaviour, UnseenVoxelsStayUnknownAndDarkPixelsCarve) {
  auto carver = make();
  view(*carver, ringImage(sonar_, 2.01, 50.0f), sonarAt(0.0));
  EXPECT_EQ(valueAt(*carver, {1.51, 0.0, 0.0}), 0.0f);                // dark bin: carved
  EXPECT_EQ(valueAt(*carver, {2.01, 0.0, 0.3}), VoxelMap::kUnknown);  // 8.5 deg below
  EXPECT_EQ(valueAt(*carver, {2.01, 0.3, 0.0}), VoxelMap::kUnknown);  // 8.5 deg starboard
  EXPECT_EQ(valueAt(*carver, {3.3, 0.0, 0.0}), VoxelMap::kUnknown);   // beyond 3 m
}

TEST_P(CarverBehaviour, DarkPixelsCarveUpToTheFieldOfViewsEdgesAndNoFurther) {
  // The fan's edges are at +-5 degrees; the reference engine casts arcs on its beams' centres
  // (+-4 degrees for the outer beams) at its bins' centres (2.02 m). A 2 cm voxel at 2 m spans
  // 0.6 degree, so voxels 1 degree inside an edge and 0.8 degree outside it are wholly on their
  // side of it.
  auto carver = make();
  view(*carver, ringImage(sonar_, 1.2, 50.0f), sonarAt(0.0));
  for (const double side : {-1.0, 1.0}) {
    const auto at = [&](double bearing_deg) {
      const double b = side * degToRad(bearing_deg);
      return Eigen::Vector3d(2.02 * std::cos(b), 2.02 * std::sin(b), 0.0);
    };
    EXPECT_EQ(valueAt(*carver, at(4.0)), 0.0f) << "side " << side;
    EXPECT_EQ(valueAt(*carver, at(5.8)), VoxelMap::kUnknown) << "side " << side;
  }
}

TEST_P(CarverBehaviour, ACarvedVoxelIsNeverRecreatedByALaterView) {
  auto carver = make();
  const Eigen::Vector3d p(2.01, 0.0, 0.0);
  view(*carver, ringImage(sonar_, 1.5, 50.0f), sonarAt(0.0));  // p's bin is dark: carved
  ASSERT_EQ(valueAt(*carver, p), 0.0f);
  view(*carver, ringImage(sonar_, 2.01, 90.0f), sonarAt(0.0));  // now lit
  EXPECT_EQ(valueAt(*carver, p), 0.0f);
  view(*carver, ringImage(sonar_, 2.01, 90.0f), sonarAt(0.05));
  EXPECT_EQ(valueAt(*carver, p), 0.0f);
}

TEST_P(CarverBehaviour, ElevationIsPositiveUpwards) {
  // A sonar pitched up by 4 degrees sees a voxel 6 degrees above the horizon (elevation +2)
  // but not one 6 degrees below it (elevation -10, outside the 10 degree aperture). At a bin
  // centre range and on the 0.2 degree elevation grid, arc-casting engines pass through too.
  auto carver = make();
  const double r = 2.02;
  const Eigen::Vector3d above(r * std::cos(degToRad(6)), 0.0, -r * std::sin(degToRad(6)));
  const Eigen::Vector3d below(r * std::cos(degToRad(6)), 0.0, r * std::sin(degToRad(6)));
  view(*carver, ringImage(sonar_, r, 40.0f), sonarAt(0.0, degToRad(4)));
  EXPECT_EQ(valueAt(*carver, above), 40.0f);
  EXPECT_EQ(valueAt(*carver, below), VoxelMap::kUnknown);
}

TEST_P(CarverBehaviour, ThresholdTurnsWeakPixelsIntoEmptyWater) {
  CarveParams params;
  params.intensity_threshold = 20.0;
  auto carver = make(params);
  view(*carver, ringImage(sonar_, 2.01, 15.0f), sonarAt(0.0));
  EXPECT_EQ(valueAt(*carver, {2.01, 0.0, 0.0}), 0.0f);
  EXPECT_EQ(carver->stats().occupied_voxels, 0u);
}

TEST_P(CarverBehaviour, SurfaceCandidatesAreOccupiedVoxelsFacingNonOccupiedSpace) {
  auto carver = make();
  view(*carver, ringImage(sonar_, 2.01, 50.0f), sonarAt(0.0));
  std::size_t candidates = 0;
  // Candidates lie in the lit bin [2.00, 2.04) m, give or take a voxel's half diagonal.
  const double half_diagonal = 0.5 * std::sqrt(3.0) * CarveParams::kDefaultVoxelSize_m;
  carver->forEachSurfaceCandidate([&](const Eigen::Vector3i& v, float value) {
    ++candidates;
    EXPECT_EQ(value, carver->value(v));
    EXPECT_EQ(value, 50.0f);
    const double range =
        ((v.cast<double>() + Eigen::Vector3d::Constant(0.5)) * CarveParams::kDefaultVoxelSize_m)
            .norm();
    EXPECT_GT(range, 2.0 - half_diagonal);
    EXPECT_LT(range, 2.04 + half_diagonal);
  });
  // The lit ring is one range bin (4 cm, two voxels) thick: every occupied voxel borders
  // carved water, so every one is a candidate.
  const CarverStats stats = carver->stats();
  EXPECT_GT(stats.occupied_voxels, 0u);
  EXPECT_EQ(candidates, stats.occupied_voxels);
  EXPECT_GT(stats.memory_bytes, 0u);
}

TEST_P(CarverBehaviour, RejectsAnImageOfAnotherSize) {
  auto carver = make();
  const cv::Mat wrong(10, 10, CV_32F, cv::Scalar(1.0f));
  EXPECT_THROW(view(*carver, wrong, sonarAt(0.0)), Error);
}

std::string engineName(const ::testing::TestParamInfo<CarverEngine>& info) {
  return carverEngineName(info.param);
}

INSTANTIATE_TEST_SUITE_P(EveryEngine, CarverBehaviour, ::testing::ValuesIn(carverEngines()),
                         engineName);

TEST(CarverRegistry, NamesAndKeysGoBothWays) {
  for (const CarverEngine key : carverEngines()) {
    EXPECT_EQ(carverEngineFromName(carverEngineName(key)), key);
  }
  EXPECT_EQ(carverEngineFromName("fast"), CarverEngine::Fast);
  EXPECT_EQ(carverEngineFromName("reference"), CarverEngine::Reference);
  EXPECT_FALSE(carverEngineFromName("warp-drive"));
}

TEST(CarverRegistry, AnUnknownEngineIsAnError) {
  const SonarModel sonar = tinySonar();
  ThreadPool pool(1);
  CarveParams params;
  params.region = Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  EXPECT_THROW(makeCarver(CarverEngine{999}, CarverSetup{sonar, params, pool}), Error);
}

}  // namespace
}  // namespace sonarcarve
