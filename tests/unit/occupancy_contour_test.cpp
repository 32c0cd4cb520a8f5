// The occupancy mesher's tiled contour against the whole-box contour it replaces: the same
// triangles (to float rounding), whatever the tile size, with the tiles' shared vertices merged;
// and points far apart mesh without sampling the space between them.
#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkImageGaussianSmooth.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <tuple>
#include <vector>

#include "mesh/internal/occupancy_contour.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

constexpr double kVoxel = 0.02;

SurfacePoints shellPoints(const Eigen::Vector3f& centre, float radius) {
  return test::sphereShellPoints(centre, radius, static_cast<float>(kVoxel), 120);
}

using Triangle = std::array<float, 9>;

// The triangles as world coordinates, each started at its smallest vertex (winding kept),
// sorted: two surfaces are equal when these lists are.
std::vector<Triangle> canonicalTriangles(vtkPolyData* surface) {
  std::vector<Triangle> triangles;
  vtkCellArray* polys = surface->GetPolys();
  const vtkIdType* ids = nullptr;
  vtkIdType n = 0;
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);) {
    EXPECT_EQ(n, 3);
    std::array<std::array<float, 3>, 3> v{};
    for (int k = 0; k < 3; ++k) {
      double p[3];
      surface->GetPoint(ids[k], p);
      v[k] = {static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])};
    }
    const int first = static_cast<int>(std::min_element(v.begin(), v.end()) - v.begin());
    Triangle t{};
    for (int k = 0; k < 3; ++k) {
      std::copy(v[(first + k) % 3].begin(), v[(first + k) % 3].end(), t.begin() + 3 * k);
    }
    triangles.push_back(t);
  }
  std::sort(triangles.begin(), triangles.end());
  return triangles;
}

// How many of `got` have no twin in `expected` (sorted), one to one: a twin has every
// coordinate within 1e-5 m (float rounding of the smoothing sums, far below a voxel).
std::size_t unmatchedTriangles(const std::vector<Triangle>& got,
                               const std::vector<Triangle>& expected) {
  constexpr float kTolerance = 1e-5f;
  std::vector<bool> used(expected.size(), false);
  std::size_t unmatched = 0;
  for (const Triangle& given : got) {
    bool found = false;
    // Any of its rotations: rounding may change which vertex is the smallest.
    for (int r = 0; r < 3 && !found; ++r) {
      Triangle t{};
      for (int k = 0; k < 9; ++k) {
        t[k] = given[(k + 3 * r) % 9];
      }
      Triangle low = t;
      low[0] -= kTolerance;
      for (auto it = std::lower_bound(expected.begin(), expected.end(), low);
           it != expected.end() && (*it)[0] <= t[0] + kTolerance && !found; ++it) {
        const auto i = static_cast<std::size_t>(it - expected.begin());
        bool close = !used[i];
        for (int k = 0; k < 9 && close; ++k) {
          close = std::abs((*it)[k] - t[k]) <= kTolerance;
        }
        if (close) {
          used[i] = true;
          found = true;
        }
      }
    }
    unmatched += found ? 0 : 1;
  }
  return unmatched;
}

// The contour over one image holding every point (what the mesher did before tiles), in
// voxel-index coordinates as the tiles compute it, then placed in the world.
vtkSmartPointer<vtkPolyData> wholeBoxContour(const SurfacePoints& points,
                                             const OccupancyContourParams& params) {
  std::vector<Eigen::Vector3i> voxels;
  Eigen::Vector3i lo = Eigen::Vector3i::Constant(1 << 30), hi = -lo;
  for (const SurfacePoint& p : points) {
    voxels.push_back((p.position_m.cast<double>() / kVoxel).array().floor().cast<int>().matrix());
    lo = lo.cwiseMin(voxels.back());
    hi = hi.cwiseMax(voxels.back());
  }
  const int margin = 4;
  lo -= Eigen::Vector3i::Constant(margin);
  const Eigen::Vector3i dims = hi - lo + Eigen::Vector3i::Constant(margin + 1);
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(dims.x(), dims.y(), dims.z());
  image->SetOrigin(lo.x(), lo.y(), lo.z());
  image->AllocateScalars(VTK_FLOAT, 1);
  auto* values = static_cast<float*>(image->GetScalarPointer());
  std::fill(values, values + static_cast<std::size_t>(dims.prod()), 0.0f);
  for (const Eigen::Vector3i& v : voxels) {
    const Eigen::Vector3i l = v - lo;
    values[(static_cast<std::size_t>(l.z()) * dims.y() + l.y()) * dims.x() + l.x()] = 1.0f;
  }
  auto smooth = vtkSmartPointer<vtkImageGaussianSmooth>::New();
  smooth->SetInputData(image);
  smooth->SetDimensionality(3);
  smooth->SetStandardDeviations(params.sigma_voxels, params.sigma_voxels, params.sigma_voxels);
  smooth->SetRadiusFactors(2.0, 2.0, 2.0);
  auto contour = vtkSmartPointer<vtkFlyingEdges3D>::New();
  contour->SetInputConnection(smooth->GetOutputPort());
  contour->SetValue(0, params.iso);
  contour->ComputeNormalsOff();
  contour->Update();
  vtkSmartPointer<vtkPolyData> out = contour->GetOutput();
  vtkPoints* pts = out->GetPoints();
  for (vtkIdType i = 0; i < pts->GetNumberOfPoints(); ++i) {
    double p[3];
    pts->GetPoint(i, p);
    const float x = static_cast<float>(p[0]), y = static_cast<float>(p[1]),
                z = static_cast<float>(p[2]);
    pts->SetPoint(i, (x + 0.5) * kVoxel, (y + 0.5) * kVoxel, (z + 0.5) * kVoxel);
  }
  return out;
}

TEST(OccupancyContour, TilesGiveTheWholeBoxContourWithTheirSeamsJoined) {
  // A sphere of 0.4 m (40 voxels across) straddling tile borders at every tile size tried.
  const SurfacePoints points = shellPoints({1.23f, -0.71f, 2.05f}, 0.4f);
  OccupancyContourParams params;
  params.voxel_size_m = kVoxel;
  const auto whole = wholeBoxContour(points, params);
  const std::vector<Triangle> expected = canonicalTriangles(whole);
  ASSERT_GT(expected.size(), 5000u);
  for (const int tile : {5, 16, 64}) {
    params.tile_voxels = tile;
    const auto tiled = occupancyContour(points, params);
    EXPECT_EQ(tiled->GetNumberOfCells(), static_cast<vtkIdType>(expected.size()));
    EXPECT_EQ(unmatchedTriangles(canonicalTriangles(tiled), expected), 0u) << "tiles of " << tile;
    // The pieces' shared vertices are one vertex each: as many as over the whole box.
    EXPECT_EQ(tiled->GetNumberOfPoints(), whole->GetNumberOfPoints()) << "tiles of " << tile;
  }
}

TEST(OccupancyContour, PointsFarApartMeshWithoutTheSpaceBetweenThem) {
  // Two shells 2 km apart: a grid over their box would hold 10^15 samples.
  SurfacePoints points = shellPoints({0.0f, 0.0f, 10.0f}, 0.2f);
  const SurfacePoints far = shellPoints({2000.0f, 1500.0f, 30.0f}, 0.2f);
  points.insert(points.end(), far.begin(), far.end());
  OccupancyContourParams params;
  params.voxel_size_m = kVoxel;
  const auto surface = occupancyContour(points, params);
  double bounds[6];
  surface->GetBounds(bounds);
  // Both shells are there, each within a voxel or two of its points.
  EXPECT_NEAR(bounds[0], -0.2, 3 * kVoxel);
  EXPECT_NEAR(bounds[1], 2000.2, 3 * kVoxel);
  EXPECT_NEAR(bounds[3], 1500.2, 3 * kVoxel);
  EXPECT_NEAR(bounds[5], 30.2, 3 * kVoxel);
  EXPECT_GT(surface->GetNumberOfCells(), 1000);
}

TEST(OccupancyContour, NoPointsGiveAnEmptySurface) {
  EXPECT_EQ(occupancyContour({}, OccupancyContourParams{})->GetNumberOfCells(), 0);
}

}  // namespace
}  // namespace sonarcarve
