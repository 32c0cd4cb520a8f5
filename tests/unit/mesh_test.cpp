// Meshing and exports: a sphere's points give a closed mesh near the sphere; frames, crops,
// formats and atomic writes of the exporters.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "common/error.h"
#include "common/progress.h"
#include "mesh/deliverable.h"
#include "mesh/mesh_export.h"
#include "mesh/surface_mesher.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

// A sphere of radius 0.5 m at (10, 20, 30) as carving gives it: the centres of the 2 cm
// voxels its surface crosses.
SurfacePoints spherePoints() {
  return test::sphereShellPoints({10, 20, 30}, 0.5f, 0.02f, 160);
}

TEST(Mesher, OccupancyMeshLiesWithinAVoxelOfTheSurface) {
  const Mesh mesh = meshSurface(spherePoints(), MeshParams{});
  ASSERT_GT(mesh.triangles.size(), 1000u);
  ASSERT_EQ(mesh.vertices.size(), mesh.normals.size());
  ASSERT_EQ(mesh.vertices.size(), mesh.intensity.size());
  // Voxel centres lie up to half a diagonal (1.7 cm) from the sphere, the voxels a surface
  // crosses form a layer up to two voxels thick, and the skin lies up to 0.8 voxel (1.6 cm)
  // outside that layer on either side: every vertex within 3.5 cm of the sphere, half of
  // them within 1.25 voxels (2.5 cm).
  std::vector<float> errors;
  for (const auto& v : mesh.vertices) {
    errors.push_back(std::abs((v - Eigen::Vector3f(10, 20, 30)).norm() - 0.5f));
    ASSERT_LT(errors.back(), 0.035f);
  }
  std::nth_element(errors.begin(), errors.begin() + static_cast<long>(errors.size() / 2),
                   errors.end());
  EXPECT_LT(errors[errors.size() / 2], 0.025f);
  EXPECT_EQ(mesh.views.front(), 7u);  // properties come from the nearest point
}

TEST(Mesher, SmallFragmentsAreRemoved) {
  SurfacePoints points = spherePoints();
  points.push_back({Eigen::Vector3f(15, 20, 30), 50.0f, 1});  // a stray point far away
  MeshParams params;
  const Mesh mesh = meshSurface(points, params);
  for (const auto& v : mesh.vertices) {
    ASSERT_LT((v - Eigen::Vector3f(10, 20, 30)).norm(), 1.0f);
  }
  EXPECT_THROW(meshSurface(SurfacePoints(5), params), Error);
}

Mesh oneTriangle() {
  Mesh m;
  m.vertices = {{1, 2, 3}, {2, 2, 3}, {1, 3, 3}};
  m.normals = {{0, 0, -1}, {0, 0, -1}, {0, 0, -1}};
  m.triangles = {{0, 1, 2}};
  m.intensity = {1, 2, 3};
  m.views = {4, 5, 6};
  return m;
}

TEST(MeshExport, ZUpFrameSwapsNorthEastAndFlipsDown) {
  test::ScratchDir dir;
  ExportOptions options;
  options.frame = "zup";
  options.origin_ned_m = Eigen::Vector3d(1, 0, 0);
  exportMesh(oneTriangle(), dir.path() / "m.ply", options);
  const Mesh back = readMeshPly(dir.path() / "m.ply");
  ASSERT_EQ(back.vertices.size(), 3u);
  EXPECT_TRUE(back.vertices[0].isApprox(Eigen::Vector3f(2, 0, -3)));  // (e, n - 1, -d)
  EXPECT_TRUE(back.normals[0].isApprox(Eigen::Vector3f(0, 0, 1)));    // down becomes -up
  EXPECT_EQ(back.views[2], 6u);
  EXPECT_FLOAT_EQ(back.intensity[1], 2.0f);
}

TEST(MeshExport, CropKeepsTrianglesInsideTheBox) {
  test::ScratchDir dir;
  ExportOptions options;
  options.crop_ned_m = Eigen::AlignedBox3d(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1.5, 5, 5));
  EXPECT_THROW(exportMesh(oneTriangle(), dir.path() / "m.ply", options), Error);
  options.crop_ned_m = Eigen::AlignedBox3d(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(5, 5, 5));
  exportMesh(oneTriangle(), dir.path() / "m.ply", options);
  EXPECT_EQ(readMeshPly(dir.path() / "m.ply").triangles.size(), 1u);
}

TEST(MeshExport, AFailedExportKeepsThePreviousFile) {
  test::ScratchDir dir;
  const auto path = dir.path() / "deliverable.stl";
  ExportOptions stl;
  stl.format = "stl";
  exportMesh(oneTriangle(), path, stl);
  const std::string before = test::readText(path);
  Mesh empty;
  EXPECT_THROW(exportMesh(empty, path, stl), Error);
  EXPECT_EQ(test::readText(path), before);
  ExportOptions bad;
  bad.format = "dwg";
  EXPECT_THROW(exportMesh(oneTriangle(), dir.path() / "x.dwg", bad), Error);
  EXPECT_THROW(formatOfPath("mesh.dxf"), Error);
  EXPECT_EQ(formatOfPath("MESH.STL"), "stl");
}

// The workbench's Cancel: the export stops before it writes, the previous file as it was.
TEST(MeshExport, ACancelledExportWritesNothing) {
  test::ScratchDir dir;
  const auto path = dir.path() / "points.las";
  test::writeText(path, "the previous deliverable\n");
  ExportOptions las;
  las.format = "las";
  SilentProgress progress;
  progress.cancel();
  EXPECT_THROW(exportPoints(spherePoints(), path, las, &progress), Cancelled);
  EXPECT_THROW(exportMesh(oneTriangle(), dir.path() / "m.ply", ExportOptions{}, &progress),
               Cancelled);
  EXPECT_EQ(test::readText(path), "the previous deliverable\n");
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "m.ply"));
}

// One request, the CLI's or the workbench's: the product it is made of, and what it says.
TEST(Deliverable, MadeOfTheProductItsFormatNeeds) {
  test::ScratchDir dir;
  DeliverableRequest request;
  request.options.format = "obj";
  EXPECT_FALSE(madeFromPoints(request));
  const Mesh mesh = oneTriangle();
  const SurfacePoints points = spherePoints();
  try {
    writeDeliverable(request, DeliverableSource{nullptr, &points}, dir.path() / "m.obj");
    ADD_FAILURE() << "a mesh deliverable without a mesh was written";
  } catch (const Error& e) {
    EXPECT_EQ(e.source(), (dir.path() / "m.obj").string());
    EXPECT_NE(e.message().find("no mesh"), std::string::npos) << e.what();
  }
  writeDeliverable(request, DeliverableSource{&mesh, nullptr}, dir.path() / "m.obj");
  EXPECT_NE(test::readText(dir.path() / "m.obj").find("\nf 1//1 2//2 3//3\n"), std::string::npos);
  EXPECT_EQ(deliverableSummary(request), "obj, ned frame, local to the origin 0 0 0");
  request.options.format = "las";
  request.options.mission_crs = "EPSG:32631";
  EXPECT_TRUE(madeFromPoints(request));
  EXPECT_EQ(deliverableSummary(request),
            "las, x east, y north, z up, world coordinates in EPSG:32631");
  request.options.format = "ply";
  request.points = true;
  request.options.add_mission_origin = true;
  EXPECT_TRUE(madeFromPoints(request));
  EXPECT_EQ(deliverableSummary(request), "ply, ned frame, world coordinates");
}

}  // namespace
}  // namespace sonarcarve
