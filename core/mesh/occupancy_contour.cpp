#include "mesh/internal/occupancy_contour.h"

#include <vtkCellArray.h>
#include <vtkExtractVOI.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkImageGaussianSmooth.h>
#include <vtkPoints.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "common/floor_div.h"

namespace sonarcarve {
namespace {

// A tile's key: its three tile indices, 21 bits each (tiles of 64 voxels reach far past the
// map's +-32768 voxels).
std::uint64_t tileKey(const Eigen::Vector3i& t) {
  const auto bits = [](int v) { return static_cast<std::uint64_t>(v + (1 << 20)) & 0x1FFFFF; };
  return bits(t.x()) | bits(t.y()) << 21 | bits(t.z()) << 42;
}

Eigen::Vector3i tileOfKey(std::uint64_t key) {
  const auto axis = [&](int shift) {
    return static_cast<int>((key >> shift) & 0x1FFFFF) - (1 << 20);
  };
  return {axis(0), axis(21), axis(42)};
}

// The points' voxels, listed under every tile whose smoothing border holds them.
std::unordered_map<std::uint64_t, std::vector<Eigen::Vector3i>> voxelsByTile(
    const SurfacePoints& points, double voxel_size_m, int tile, int border) {
  std::unordered_map<std::uint64_t, std::vector<Eigen::Vector3i>> tiles;
  for (const SurfacePoint& p : points) {
    const Eigen::Vector3i v =
        (p.position_m.cast<double>() / voxel_size_m).array().floor().cast<int>().matrix();
    // Tile t holds samples [t * tile - border, (t + 1) * tile + border]: the tiles from
    // ceil((v - border) / tile) - 1 to floor((v + border) / tile).
    Eigen::Vector3i first, last;
    for (int a = 0; a < 3; ++a) {
      first[a] = floorDiv(v[a] - border - 1, tile);
      last[a] = floorDiv(v[a] + border, tile);
    }
    for (int z = first.z(); z <= last.z(); ++z) {
      for (int y = first.y(); y <= last.y(); ++y) {
        for (int x = first.x(); x <= last.x(); ++x) {
          tiles[tileKey({x, y, z})].push_back(v);
        }
      }
    }
  }
  return tiles;
}

// One tile's contour, in voxel-index coordinates (sample i at i), over its cells
// [t * tile, (t + 1) * tile).
vtkSmartPointer<vtkPolyData> tileContour(const Eigen::Vector3i& t,
                                         const std::vector<Eigen::Vector3i>& voxels,
                                         const OccupancyContourParams& params, int border) {
  const int tile = params.tile_voxels;
  const int side = tile + 1 + 2 * border;
  const Eigen::Vector3i origin = t * tile - Eigen::Vector3i::Constant(border);
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(side, side, side);
  image->SetSpacing(1.0, 1.0, 1.0);
  image->SetOrigin(origin.x(), origin.y(), origin.z());
  image->AllocateScalars(VTK_FLOAT, 1);
  auto* values = static_cast<float*>(image->GetScalarPointer());
  std::fill(values, values + static_cast<std::size_t>(side) * side * side, 0.0f);
  for (const Eigen::Vector3i& v : voxels) {
    const Eigen::Vector3i l = v - origin;
    values[(static_cast<std::size_t>(l.z()) * side + l.y()) * side + l.x()] = 1.0f;
  }
  auto smooth = vtkSmartPointer<vtkImageGaussianSmooth>::New();
  smooth->SetInputData(image);
  smooth->SetDimensionality(3);
  const double sigma = params.sigma_voxels;
  smooth->SetStandardDeviations(sigma, sigma, sigma);
  smooth->SetRadiusFactors(2.0, 2.0, 2.0);
  auto core = vtkSmartPointer<vtkExtractVOI>::New();
  core->SetInputConnection(smooth->GetOutputPort());
  core->SetVOI(border, border + tile, border, border + tile, border, border + tile);
  auto contour = vtkSmartPointer<vtkFlyingEdges3D>::New();
  contour->SetInputConnection(core->GetOutputPort());
  contour->SetValue(0, params.iso);
  contour->ComputeNormalsOff();
  contour->ComputeGradientsOff();
  contour->ComputeScalarsOff();
  contour->Update();
  return contour->GetOutput();
}

// A contour vertex lies on a grid edge: the edge's lower sample and its axis (3: on the
// sample itself) name it whatever the last bits of its interpolated coordinate.
using EdgeKey = std::array<int, 4>;
struct EdgeKeyHash {
  std::size_t operator()(const EdgeKey& k) const {
    std::size_t h = 0;
    for (const int c : k) {
      h = h * 0x9E3779B97F4A7C15ull + static_cast<std::size_t>(static_cast<unsigned>(c));
    }
    return h;
  }
};

EdgeKey edgeOf(const double x[3]) {
  EdgeKey key{0, 0, 0, 3};
  for (int a = 0; a < 3; ++a) {
    const double lower = std::floor(x[a]);
    key[static_cast<std::size_t>(a)] = static_cast<int>(lower);
    if (x[a] != lower) {
      key[3] = a;
    }
  }
  return key;
}

// Joins the tiles' pieces: a vertex on a tile's border plane is on an edge the neighbouring
// piece contours too, from the same sample values, and is merged with its twin; others are new.
class TileJoiner {
 public:
  explicit TileJoiner(double voxel_size_m) : voxel_size_m_(voxel_size_m) {
    points_->SetDataTypeToFloat();
  }
  void add(vtkPolyData* piece, const Eigen::Vector3i& lo, const Eigen::Vector3i& hi) {
    std::vector<vtkIdType> ids(static_cast<std::size_t>(piece->GetNumberOfPoints()));
    for (vtkIdType i = 0; i < piece->GetNumberOfPoints(); ++i) {
      double x[3];
      piece->GetPoint(i, x);
      bool on_border = false;
      for (int a = 0; a < 3; ++a) {
        on_border = on_border || x[a] == lo[a] || x[a] == hi[a];
      }
      if (on_border) {
        const auto [it, added] = border_.try_emplace(edgeOf(x), points_->GetNumberOfPoints());
        ids[static_cast<std::size_t>(i)] = it->second;
        if (!added) {
          continue;
        }
      } else {
        ids[static_cast<std::size_t>(i)] = points_->GetNumberOfPoints();
      }
      points_->InsertNextPoint((x[0] + 0.5) * voxel_size_m_, (x[1] + 0.5) * voxel_size_m_,
                               (x[2] + 0.5) * voxel_size_m_);
    }
    vtkCellArray* polys = piece->GetPolys();
    const vtkIdType* cell = nullptr;
    vtkIdType n = 0;
    for (polys->InitTraversal(); polys->GetNextCell(n, cell);) {
      std::array<vtkIdType, 3> triangle{};
      for (vtkIdType k = 0; k < 3 && k < n; ++k) {
        triangle[static_cast<std::size_t>(k)] = ids[static_cast<std::size_t>(cell[k])];
      }
      triangles_->InsertNextCell(3, triangle.data());
    }
  }
  vtkSmartPointer<vtkPolyData> surface() const {
    auto out = vtkSmartPointer<vtkPolyData>::New();
    out->SetPoints(points_);
    out->SetPolys(triangles_);
    return out;
  }

 private:
  double voxel_size_m_;
  vtkSmartPointer<vtkPoints> points_ = vtkSmartPointer<vtkPoints>::New();
  vtkSmartPointer<vtkCellArray> triangles_ = vtkSmartPointer<vtkCellArray>::New();
  std::unordered_map<EdgeKey, vtkIdType, EdgeKeyHash> border_;
};

}  // namespace

vtkSmartPointer<vtkPolyData> occupancyContour(const SurfacePoints& points,
                                              const OccupancyContourParams& params) {
  // vtkImageGaussianSmooth reaches int(sigma * radius factor) samples; one more for safety.
  const int border = static_cast<int>(params.sigma_voxels * 2.0) + 1;
  const int tile = params.tile_voxels;
  auto by_tile = voxelsByTile(points, params.voxel_size_m, tile, border);
  std::vector<std::uint64_t> keys;
  keys.reserve(by_tile.size());
  for (const auto& entry : by_tile) {
    keys.push_back(entry.first);
  }
  std::sort(keys.begin(), keys.end());
  TileJoiner joiner(params.voxel_size_m);
  for (const std::uint64_t key : keys) {
    const Eigen::Vector3i t = tileOfKey(key);
    std::vector<Eigen::Vector3i>& voxels = by_tile[key];
    const auto piece = tileContour(t, voxels, params, border);
    joiner.add(piece, t * tile, (t + Eigen::Vector3i::Ones()) * tile);
    std::vector<Eigen::Vector3i>().swap(voxels);
  }
  return joiner.surface();
}

}  // namespace sonarcarve
