// Heading sectors (pipeline/heading_sectors.h) and what they set back into a mission's map
// (pipeline/sector_restore.h): views grouped by where they look on the compass; a face one
// sector keeps is set back unless another sector carved it while looking at it nearly
// head-on, with nothing of the scene between them.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "common/angles.h"
#include "pipeline/heading_sectors.h"
#include "pipeline/sector_restore.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

constexpr double kVoxel = 0.02;
constexpr double kRange = 10.0;

// A sonar at `at` looking horizontally at compass heading `heading_deg`, pitched `pitch_deg`.
PosedFrame looking(double heading_deg, const Eigen::Vector3d& at = Eigen::Vector3d::Zero(),
                   double pitch_deg = 0.0) {
  PosedFrame frame;
  frame.T_world_sonar.linear() =
      (Eigen::AngleAxisd(degToRad(heading_deg), Eigen::Vector3d::UnitZ()) *
       Eigen::AngleAxisd(degToRad(pitch_deg), Eigen::Vector3d::UnitY()))
          .toRotationMatrix();
  frame.T_world_sonar.translation() = at;
  return frame;
}

// An orbit of `count` frames at `radius` around the origin, each looking at it.
std::vector<PosedFrame> orbit(std::size_t count, double radius) {
  std::vector<PosedFrame> frames;
  for (std::size_t i = 0; i < count; ++i) {
    const double heading = 360.0 * static_cast<double>(i) / static_cast<double>(count);
    const double a = degToRad(heading);
    frames.push_back(looking(heading, -radius * Eigen::Vector3d(std::cos(a), std::sin(a), 0.0)));
    frames.back().index = i;
  }
  return frames;
}

TEST(HeadingSectors, AnOrbitSplitsIntoSixtyDegreeSectorsInTheMissionsOrder) {
  const std::vector<std::vector<PosedFrame>> sectors = headingSectors(orbit(288, 5.0));
  ASSERT_EQ(sectors.size(), 6u);
  std::size_t frames = 0;
  for (const std::vector<PosedFrame>& sector : sectors) {
    EXPECT_NEAR(static_cast<double>(sector.size()), 48.0, 1.0);  // a heading on an edge
    frames += sector.size();
    for (std::size_t i = 1; i < sector.size(); ++i) {
      EXPECT_LT(sector[i - 1].index, sector[i].index);
    }
  }
  EXPECT_EQ(frames, 288u);
  EXPECT_EQ(sectorsToCarve(orbit(288, 5.0), kRange).size(), 6u);
}

TEST(HeadingSectors, DescentsFromFourSidesAreFourSectorsAndOnePassIsOne) {
  std::vector<PosedFrame> descents;
  for (const double heading : {0.0, 90.0, 180.0, 270.0}) {
    for (int i = 0; i < 30; ++i) {
      descents.push_back(looking(heading + 0.1 * i, Eigen::Vector3d(0.0, 0.0, 0.1 * i)));
    }
  }
  EXPECT_EQ(headingSectors(descents).size(), 4u);
  const std::vector<PosedFrame> one_pass(descents.begin(), descents.begin() + 30);
  EXPECT_EQ(headingSectors(one_pass).size(), 1u);
  EXPECT_TRUE(sectorsToCarve(one_pass, kRange).empty());
}

TEST(HeadingSectors, FramesLookingDownAndSmallSectorsAreLeftOut) {
  std::vector<PosedFrame> frames;
  for (int i = 0; i < 40; ++i) {
    frames.push_back(looking(30.0 * i, Eigen::Vector3d::Zero(), -89.0));  // straight down
  }
  EXPECT_TRUE(headingSectors(frames).empty());
  for (int i = 0; i < 30; ++i) {
    frames.push_back(looking(0.0));
  }
  for (int i = 0; i < 10; ++i) {
    frames.push_back(looking(180.0));  // fewer than kSectorMinFrames
  }
  const auto sectors = headingSectors(frames);
  ASSERT_EQ(sectors.size(), 1u);
  EXPECT_EQ(sectors[0].size(), 30u);
}

TEST(HeadingSectors, ASurveysLinesAreNotCarvedBySector) {
  std::vector<PosedFrame> lines;  // a lawnmower: 20 m lines there and back, 3 m apart
  for (int line = 0; line < 2; ++line) {
    for (int i = 0; i < 40; ++i) {
      lines.push_back(looking(line == 0 ? 0.0 : 180.0,
                              Eigen::Vector3d(0.5 * (line == 0 ? i : 40 - i), 3.0 * line, 0.0)));
    }
  }
  EXPECT_EQ(headingSectors(lines).size(), 2u);
  EXPECT_TRUE(sectorsToCarve(lines, kRange).empty());
}

TEST(ElevationSwept, ADescentSweepsItsBeamOverAPointAndALevelArcDoesNot) {
  const SonarModel sonar = test::paperSonar();
  SurfacePoints point(1);
  point[0].position_m = Eigen::Vector3f(3.0f, 0.0f, 0.5f);  // 3 m ahead, 0.5 m down
  std::vector<PosedFrame> descent;
  std::vector<PosedFrame> arc;
  for (int i = 0; i < 30; ++i) {
    descent.push_back(looking(0.0, Eigen::Vector3d(0.0, 0.0, -0.5 + 0.067 * i)));
    const double a = degToRad(-15.0 + i);  // around the point, at one height
    arc.push_back(
        looking(radToDeg(a), Eigen::Vector3d(3.0 - 3.0 * std::cos(a), -3.0 * std::sin(a), 0.0)));
  }
  const double aperture = sonar.verticalAperture();
  EXPECT_TRUE(elevationSwept(point, descent, sonar, aperture)[0]);
  EXPECT_FALSE(elevationSwept(point, arc, sonar, 0.1 * aperture)[0]);
}

TEST(SurfaceNormals, AreTheNormalOfAPlaneAndNoneForAFewVoxels) {
  std::vector<Eigen::Vector3i> plane;  // a plane tilted about x: normal (0, -1, 1) / sqrt 2
  for (int x = 0; x < 10; ++x) {
    for (int y = 0; y < 10; ++y) {
      plane.emplace_back(x, y, y);
    }
  }
  const std::vector<Eigen::Vector3f> normals = surfaceNormals(plane);
  const Eigen::Vector3f truth = Eigen::Vector3f(0.0f, -1.0f, 1.0f).normalized();
  EXPECT_NEAR(std::abs(normals[55].dot(truth)), 1.0f, 1e-4f);
  EXPECT_TRUE(surfaceNormals({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})[0].isZero());
}

// A wall of voxels in the plane north = 1 m (normal along north), 40 x 40 voxels.
SurfacePoints wall(double north_m) {
  SurfacePoints points;
  for (int e = 0; e < 40; ++e) {
    for (int d = 0; d < 40; ++d) {
      SurfacePoint p;
      p.position_m =
          Eigen::Vector3f(static_cast<float>(north_m), static_cast<float>((e + 0.5) * kVoxel),
                          static_cast<float>((d + 0.5) * kVoxel));
      points.push_back(p);
    }
  }
  return points;
}

const Eigen::AlignedBox3d kBox(Eigen::Vector3d(-4.0, -4.0, -2.0), Eigen::Vector3d(4.0, 4.0, 2.0));

// A map over kBox in which `points` hold `value` and a slab around the walls (north 0.6 to
// 2.2 m, east and down -0.2 to 1 m) is carved.
std::unique_ptr<VoxelMap> mapWith(const SurfacePoints& points, float value) {
  auto map = std::make_unique<VoxelMap>(kVoxel, kBox);
  std::vector<std::pair<Eigen::Vector3i, float>> voxels;
  Eigen::Vector3i v;
  for (v.z() = -10; v.z() < 50; ++v.z()) {
    for (v.y() = -10; v.y() < 50; ++v.y()) {
      for (v.x() = 30; v.x() < 110; ++v.x()) {
        voxels.emplace_back(v, 0.0f);
      }
    }
  }
  for (const SurfacePoint& p : points) {
    voxels.emplace_back(map->voxelOf(p.position_m.cast<double>()), value);
  }
  map->setVoxels(voxels);
  return map;
}

TEST(SectorRestore, AFaceCarvedOnlyAtGrazingIncidenceIsSetBack) {
  const SurfacePoints face = wall(1.0);
  const auto mission = mapWith({}, 0.0f);  // the mission's map carved the face
  const auto seen = mapWith(face, 50.0f);  // the sector that faces it keeps it
  const auto grazing = mapWith({}, 0.0f);  // a sector looking along the face carved it
  std::vector<SectorCarve> sectors(2);
  sectors[0] = {seen.get(), face, Eigen::Vector3d(-3.0, 0.4, 0.4)};  // head-on, from the south
  sectors[1] = {grazing.get(), {}, Eigen::Vector3d(0.9, 3.9, 0.4)};  // 88 degrees off
  const SectorRestoreCount count = restoreSectorSurfaces(*mission, sectors);
  EXPECT_EQ(count.candidates, face.size());
  EXPECT_EQ(count.restored, face.size());
  EXPECT_EQ(count.vetoed, 0u);
  EXPECT_FLOAT_EQ(mission->value(mission->voxelOf(face[820].position_m.cast<double>())), 50.0f);
}

TEST(SectorRestore, AFaceCarvedByAnotherSectorLookingAtItHeadOnStaysCarved) {
  const SurfacePoints face = wall(1.0);
  const auto mission = mapWith({}, 0.0f);
  const auto seen = mapWith(face, 50.0f);
  const auto opposite = mapWith({}, 0.0f);
  std::vector<SectorCarve> sectors(2);
  sectors[0] = {seen.get(), face, Eigen::Vector3d(-3.0, 0.4, 0.4)};
  sectors[1] = {opposite.get(), {}, Eigen::Vector3d(3.5, 0.4, 0.4)};  // from the north, 0 degrees
  const SectorRestoreCount count = restoreSectorSurfaces(*mission, sectors);
  EXPECT_EQ(count.restored, 0u);
  EXPECT_EQ(count.vetoed, face.size() - count.no_normal);
  EXPECT_EQ(mission->value(mission->voxelOf(face[820].position_m.cast<double>())), 0.0f);
}

TEST(SectorRestore, ASectorThatAnotherSurfaceHidesFromTheFaceVetoesNothing) {
  const SurfacePoints face = wall(1.0);
  const SurfacePoints screen = wall(2.0);  // between the face and the northern sector
  const auto mission = mapWith({}, 0.0f);
  const auto seen = mapWith(face, 50.0f);
  const auto opposite = mapWith(screen, 50.0f);  // keeps the screen, carved the face
  std::vector<SectorCarve> sectors(2);
  sectors[0] = {seen.get(), face, Eigen::Vector3d(-3.0, 0.4, 0.4)};
  sectors[1] = {opposite.get(), screen, Eigen::Vector3d(3.5, 0.4, 0.4)};
  const SectorRestoreCount count = restoreSectorSurfaces(*mission, sectors);
  // The face is set back; the screen too, which the mission's map had carved.
  EXPECT_EQ(count.restored, face.size() + screen.size());
  EXPECT_FLOAT_EQ(mission->value(mission->voxelOf(face[820].position_m.cast<double>())), 50.0f);
}

TEST(SectorRestore, WhatTheMissionsMapKeptIsLeftAsItIs) {
  const SurfacePoints face = wall(1.0);
  const auto mission = mapWith(face, 20.0f);
  const auto seen = mapWith(face, 50.0f);
  const auto grazing = mapWith({}, 0.0f);
  std::vector<SectorCarve> sectors(2);
  sectors[0] = {seen.get(), face, Eigen::Vector3d(-3.0, 0.4, 0.4)};
  sectors[1] = {grazing.get(), {}, Eigen::Vector3d(0.9, 3.9, 0.4)};
  EXPECT_EQ(restoreSectorSurfaces(*mission, sectors).restored, 0u);
  EXPECT_FLOAT_EQ(mission->value(mission->voxelOf(face[820].position_m.cast<double>())), 20.0f);
}

}  // namespace
}  // namespace sonarcarve
