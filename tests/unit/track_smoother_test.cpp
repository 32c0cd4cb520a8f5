// The correction track solved from per-frame measurements and the navigation's random walk:
// a map's shared offset is not taken for drift, a direction no frame observes stays where the
// navigation put it, and no correction leaves the search window.
#include <gtest/gtest.h>

#include <cmath>

#include "carve/track_smoother.h"
#include "common/angles.h"
#include "common/error.h"

namespace sonarcarve {
namespace {

constexpr double kVoxel = 0.02;

// A measurement of `x` as precise as `sigma` (metres and radians alike) on every axis.
PoseMeasurement measured(const Vector6d& x, double sigma) {
  PoseMeasurement m;
  m.correction = PoseCorrection::of(x);
  m.correction.aligned = true;
  m.information = Matrix6d::Identity() / (sigma * sigma);
  return m;
}

// A drift that starts at the navigation and wanders half a centimetre a frame north, and east.
Vector6d drift(int i) {
  Vector6d x = Vector6d::Zero();
  x[0] = 0.005 * i;
  x[1] = 0.05 * std::sin(0.2 * i);
  return x;
}

TEST(TrackSmoother, AnOffsetSharedByEveryMeasurementIsTheMapsNotTheTracks) {
  // Every frame measured against a map that sits 10 cm off along north and east: the track
  // starts from the navigation, so the offset is the map's and the corrections are the drift.
  Vector6d map_offset = Vector6d::Zero();
  map_offset[0] = 0.1;
  map_offset[1] = -0.1;
  std::vector<PoseMeasurement> m;
  for (int i = 0; i < 60; ++i) {
    m.push_back(measured(drift(i) + map_offset, 0.5 * kVoxel));
  }
  const std::vector<Vector6d> track = smoothCorrectionTrack(m, PoseRefinementParams{});
  ASSERT_EQ(track.size(), m.size());
  for (std::size_t i = 0; i < track.size(); ++i) {
    EXPECT_LT((track[i] - drift(static_cast<int>(i))).head<3>().norm(), 0.5 * kVoxel) << i;
  }
}

TEST(TrackSmoother, ADirectionNoFrameObservesStaysAtTheNavigation) {
  // Frames that observe north only (a vertical pipe seen from the south observes neither down
  // nor pitch): whatever the measurements say along the other axes, they stay at zero.
  std::vector<PoseMeasurement> m;
  for (int i = 0; i < 40; ++i) {
    Vector6d x = Vector6d::Constant(0.03);
    x[0] = drift(i)[0];
    PoseMeasurement one = measured(x, 0.01);
    one.information = Matrix6d::Zero();
    one.information(0, 0) = 1.0 / (0.01 * 0.01);
    m.push_back(one);
  }
  m[7].correction.aligned = false;  // and one frame without a measurement
  const std::vector<Vector6d> track = smoothCorrectionTrack(m, PoseRefinementParams{});
  for (std::size_t i = 0; i < track.size(); ++i) {
    EXPECT_LT(track[i].tail<5>().cwiseAbs().maxCoeff(), 1e-9) << i;
  }
  EXPECT_GT(track.back()[0], 0.15);  // the observed axis follows its measurements
}

TEST(TrackSmoother, NoCorrectionLeavesTheSearchWindow) {
  PoseRefinementParams window;
  window.max_translation_m = 0.05;
  window.max_rotation_rad = degToRad(0.5);
  std::vector<PoseMeasurement> m;
  for (int i = 0; i < 30; ++i) {
    Vector6d x;
    x << 0.01 * i, -0.01 * i, 0.0, 0.0, 0.0, degToRad(0.1 * i);
    m.push_back(measured(x, 0.01));
  }
  for (const Vector6d& c : smoothCorrectionTrack(m, window)) {
    EXPECT_LE(c.head<3>().cwiseAbs().maxCoeff(), window.max_translation_m);
    EXPECT_LE(c.tail<3>().cwiseAbs().maxCoeff(), window.max_rotation_rad);
  }
}

TEST(TrackSmoother, ANavigationModelWithoutDriftIsAnError) {
  PoseRefinementParams p;
  p.step_sigma_m = 0.0;
  EXPECT_THROW(smoothCorrectionTrack({measured(Vector6d::Zero(), 0.01)}, p), Error);
  EXPECT_TRUE(smoothCorrectionTrack({}, PoseRefinementParams{}).empty());
}

}  // namespace
}  // namespace sonarcarve
