// Evaluation against a ground-truth mesh, on a plate whose distances are known exactly.
#include <gtest/gtest.h>

#include <cmath>

#include "eval/evaluator.h"
#include "support/sim_scenes.h"

namespace sonarcarve {
namespace {

TEST(MeshDistance, GivesTheDistanceToThePlateAndCapsItWhenAsked) {
  // A 2 m plate in the plane x = 3, facing -x.
  const Scene plate = test::plate({3, 0, 0}, {-1, 0, 0}, 2.0, 0.8f);
  ThreadPool pool(2);
  const MeshDistance distance(plate, pool);
  const std::vector<Eigen::Vector3f> points = {
      {3.0f, 0.2f, -0.4f}, {2.95f, 0.0f, 0.0f}, {2.0f, 0.5f, 0.5f}, {3.0f, 1.5f, 0.0f}};
  const std::vector<float> exact = distance.distances(points);
  ASSERT_EQ(exact.size(), 4u);
  EXPECT_NEAR(exact[0], 0.0, 1e-5);
  EXPECT_NEAR(exact[1], 0.05, 1e-5);
  EXPECT_NEAR(exact[2], 1.0, 1e-5);
  EXPECT_NEAR(exact[3], 0.5, 1e-5);  // beyond the plate's edge at y = 1
  const std::vector<float> capped = distance.distances(points, 0.2);
  EXPECT_NEAR(capped[0], 0.0, 1e-5);
  EXPECT_NEAR(capped[1], 0.05, 1e-5);
  EXPECT_FLOAT_EQ(capped[2], 0.2f);
  EXPECT_FLOAT_EQ(capped[3], 0.2f);
}

TEST(Evaluation, SplitsCompletenessByTheOrientationOfTheFaces) {
  // A wall (normal horizontal) and a deck (normal vertical), 2 m each, 2 m apart; the
  // reconstruction found the wall only.
  Scene scene = test::plate({3, 0, 0}, {-1, 0, 0}, 2.0, 0.8f);
  const Scene deck = test::plate({0, 0, 3}, {0, 0, -1}, 2.0, 0.8f);
  scene.append(deck);
  const std::vector<Eigen::Vector3f> wall_points =
      sampleSurface(test::plate({3, 0, 0}, {-1, 0, 0}, 2.0, 0.8f), 0.01);
  ThreadPool pool(2);
  const EvaluationResult r = evaluate(wall_points, scene, {}, pool);
  EXPECT_NEAR(r.completeness_other, 1.0, 1e-9);
  EXPECT_NEAR(r.completeness_horizontal, 0.0, 1e-9);
  EXPECT_EQ(r.reference_points_horizontal + r.reference_points_other, r.reference_points);
  // Equal plates, sampled alike (each point's nearest face is its own plate's).
  EXPECT_EQ(r.reference_points_horizontal, r.reference_points_other);
  EXPECT_NEAR(r.completeness, 0.5, 1e-9);
  // A roof tilted 25 degrees off level still counts as horizontal; at 35 degrees it does not.
  for (const auto& [tilt_deg, horizontal] : {std::pair{25.0, true}, std::pair{35.0, false}}) {
    const double tilt = tilt_deg * 3.14159265358979 / 180.0;
    const Scene roof = test::plate({0, 0, 3}, {std::sin(tilt), 0, -std::cos(tilt)}, 2.0, 0.8f);
    const EvaluationResult r_roof = evaluate(sampleSurface(roof, 0.1), roof, {}, pool);
    EXPECT_EQ(r_roof.reference_points_horizontal > 0, horizontal) << tilt_deg;
    EXPECT_EQ(r_roof.reference_points_other > 0, !horizontal) << tilt_deg;
  }
}

}  // namespace
TEST(Evaluate, SamplesALargeReferenceCoarselyAndSaysHowCoarsely) {
  const Scene plate = test::plate({3, 0, 0}, {-1, 0, 0}, 2.0, 0.8f);
  EXPECT_EQ(sampleCount(plate, 0.05), static_cast<double>(sampleSurface(plate, 0.05).size()));
  ThreadPool pool(2);
  const std::vector<Eigen::Vector3f> points = {{3, 0, 0}, {3, 0.5f, 0.5f}};
  const EvaluationResult fine = evaluate(points, plate, {}, pool);
  EXPECT_DOUBLE_EQ(fine.reference_spacing_m, 0.01);
  Scene big = plate;
  for (Eigen::Vector3f& v : big.vertices) {
    v *= 1000.0f;  // 2 km square: 4e10 points at 1 cm
  }
  const EvaluationResult coarse = evaluate(points, big, {}, pool);
  EXPECT_GT(coarse.reference_spacing_m, 0.01);
  EXPECT_LE(static_cast<double>(coarse.reference_points), kMaxReferenceSamples);
  EXPECT_EQ(evaluate(points, plate, points, pool).reference_spacing_m, 0.0);
}

}  // namespace sonarcarve
