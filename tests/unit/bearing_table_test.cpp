#include <gtest/gtest.h>

#include "common/angles.h"
#include "common/error.h"
#include "sonar/bearing_table.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

TEST(BearingTable, UniformTableIsSymmetricWithExactEdges) {
  const BearingTable t = BearingTable::uniform(degToRad(130), 650);
  ASSERT_EQ(t.count(), 650);
  EXPECT_TRUE(t.isUniform());
  EXPECT_DOUBLE_EQ(t.fieldOfView(), degToRad(130));
  EXPECT_DOUBLE_EQ(t.leftEdge(), -degToRad(65));
  EXPECT_DOUBLE_EQ(t.rightEdge(), degToRad(65));
  EXPECT_NEAR(t.centre(0), -degToRad(65 - 0.1), 1e-12);
  for (int j = 0; j < t.count(); ++j) {
    EXPECT_NEAR(t.centre(j), -t.centre(t.count() - 1 - j), 1e-12);
  }
}

TEST(BearingTable, EveryBeamCentreMapsToItsBeam) {
  for (const auto& table :
       {BearingTable::uniform(degToRad(130), 650), test::nonUniformSonar().bearings()}) {
    for (int j = 0; j < table.count(); ++j) {
      ASSERT_EQ(table.beamOf(table.centre(j)), j) << "beam " << j;
    }
  }
}

TEST(BearingTable, BeamBoundariesLieHalfwayBetweenNonUniformCentres) {
  const BearingTable t = BearingTable::fromCentres({-0.5, -0.1, 0.0, 0.3});
  EXPECT_FALSE(t.isUniform());
  EXPECT_EQ(t.beamOf(-0.3 - 1e-9), 0);
  EXPECT_EQ(t.beamOf(-0.3 + 1e-9), 1);
  EXPECT_EQ(t.beamOf(0.15 - 1e-9), 2);
  EXPECT_EQ(t.beamOf(0.15 + 1e-9), 3);
  // Outer beams extend by half their spacing to the neighbour.
  EXPECT_DOUBLE_EQ(t.leftEdge(), -0.7);
  EXPECT_DOUBLE_EQ(t.rightEdge(), 0.45);
  EXPECT_EQ(t.beamOf(-0.7 - 1e-9), std::nullopt);
  EXPECT_EQ(t.beamOf(0.45), std::nullopt);
  EXPECT_EQ(t.beamOf(NAN), std::nullopt);
}

TEST(BearingTable, MedianSpacingIsTheMiddleGapBetweenCentres) {
  EXPECT_NEAR(BearingTable::uniform(degToRad(130), 650).medianSpacing(), degToRad(0.2), 1e-12);
  // Gaps 0.4, 0.1, 0.3, 0.1, 0.1: the one wide gap and the slight narrowing do not move it.
  EXPECT_DOUBLE_EQ(BearingTable::fromCentres({-0.5, -0.1, 0.0, 0.3, 0.4, 0.5}).medianSpacing(),
                   0.1);
  EXPECT_EQ(BearingTable::fromCentres({0.2}).medianSpacing(), 0.0);
}

TEST(BearingTable, RejectsTablesThatDoNotIncrease) {
  EXPECT_THROW(BearingTable::fromCentres({}), Error);
  EXPECT_THROW(BearingTable::fromCentres({0.1, 0.1}), Error);
  EXPECT_THROW(BearingTable::fromCentres({0.2, 0.1}), Error);
  EXPECT_THROW(BearingTable::fromCentres({0.0, NAN}), Error);
  EXPECT_THROW(BearingTable::uniform(0.0, 10), Error);
  EXPECT_THROW(BearingTable::uniform(1.0, 0), Error);
}

}  // namespace
}  // namespace sonarcarve
