#include "map_layers.h"

#include <vtkIdTypeArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedIntArray.h>
#include <algorithm>

namespace sonarcarve::widgets {
namespace {

// Calls visit(block, k) for each point drawn: of those inside `region` (all without one), the
// points whose voxels include a multiple of `stride` when the voxels are counted in order (every
// stride-th voxel at full detail).
template <typename Visit>
void forEachDrawn(const std::vector<const MapViewBlock*>& blocks, const Eigen::AlignedBox3d* region,
                  std::size_t stride, Visit visit) {
  std::size_t seen = 0;  // voxels of the points before this one
  for (const MapViewBlock* b : blocks) {
    for (std::size_t k = 0; k < b->points.size(); ++k) {
      if (region != nullptr && !region->contains(b->points[k].cast<double>())) {
        continue;
      }
      const std::size_t next = seen + b->voxelsAt(k);
      if ((seen + stride - 1) / stride < (next + stride - 1) / stride) {
        visit(*b, k);
      }
      seen = next;
    }
  }
}

}  // namespace

MeshData meshData(const Mesh& mesh, std::vector<float> vertex_errors_m) {
  MeshData data{{}, mesh.triangles, mesh.normals};
  data.vertices.points = mesh.vertices;
  data.vertices.values = mesh.intensity;
  data.vertices.values.resize(mesh.vertices.size(), 0.0f);
  data.vertices.errors_m = std::move(vertex_errors_m);
  return data;
}

MapViewBlock surfaceBlock(const SurfacePoints& surface, std::vector<float> errors_m) {
  MapViewBlock block;
  block.points = positionsOf(surface);
  block.values.reserve(surface.size());
  for (const SurfacePoint& p : surface) {
    block.values.push_back(p.intensity);
  }
  block.errors_m = std::move(errors_m);
  return block;
}

vtkSmartPointer<vtkCellArray> pointCells(vtkIdType count, bool as_line) {
  auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
  connectivity->SetNumberOfValues(count);
  for (vtkIdType i = 0; i < count; ++i) {
    connectivity->SetValue(i, i);
  }
  if (as_line) {
    offsets->SetNumberOfValues(count > 0 ? 2 : 1);
    offsets->SetValue(0, 0);
    if (count > 0) {
      offsets->SetValue(1, count);
    }
  } else {
    offsets->SetNumberOfValues(count + 1);
    for (vtkIdType i = 0; i <= count; ++i) {
      offsets->SetValue(i, i);
    }
  }
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, connectivity);
  return cells;
}

std::size_t voxelsInside(const std::vector<const MapViewBlock*>& blocks,
                         const Eigen::AlignedBox3d* region) {
  std::size_t n = 0;
  for (const MapViewBlock* b : blocks) {
    if (region == nullptr) {
      n += b->voxelCount();
      continue;
    }
    for (std::size_t k = 0; k < b->points.size(); ++k) {
      n += region->contains(b->points[k].cast<double>()) ? b->voxelsAt(k) : 0;
    }
  }
  return n;
}

std::size_t strideFor(std::size_t count, std::size_t max_points) {
  return count <= max_points ? 1 : (count + max_points - 1) / max_points;
}

LayerColours layerColours(const std::vector<const MapViewBlock*>& blocks,
                          const Eigen::AlignedBox3d* region, std::size_t stride, ColourBy by) {
  std::vector<float> values;
  forEachDrawn(blocks, region, stride, [&](const MapViewBlock& b, std::size_t k) {
    float v = k < b.values.size() ? b.values[k] : 0.0f;
    if (by == ColourBy::Depth) {
      v = b.points[k].z();
    } else if (by == ColourBy::Error) {
      v = k < b.errors_m.size() ? b.errors_m[k] : 0.0f;
    }
    values.push_back(v);
  });
  LayerColours colours;
  colours.by = by;
  colours.scalars = vtkSmartPointer<vtkFloatArray>::New();
  colours.scalars->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
  std::copy(values.begin(), values.end(), colours.scalars->GetPointer(0));
  double range[2] = {0.0, 1.0};
  if (by == ColourBy::Error) {
    range[1] = 0.10;  // the evaluation's "floating point" distance
  } else if (by == ColourBy::Intensity && !values.empty()) {
    const auto hi =
        values.begin() + static_cast<std::ptrdiff_t>(0.98 * static_cast<double>(values.size() - 1));
    std::nth_element(values.begin(), hi, values.end());
    range[1] = std::max(1.0, static_cast<double>(*hi));
  } else if (!values.empty()) {
    colours.scalars->GetRange(range);
  }
  colours.low = range[0];
  colours.high = std::max(range[1], range[0] + 1e-6);
  return colours;
}

PreparedLayer preparePoints(const std::vector<const MapViewBlock*>& blocks,
                            const Eigen::AlignedBox3d* region, std::size_t stride, ColourBy by) {
  PreparedLayer layer;
  layer.stride = std::max<std::size_t>(1, stride);
  vtkIdType n = 0;
  forEachDrawn(blocks, region, layer.stride, [&](const MapViewBlock&, std::size_t) { ++n; });
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(n);
  auto* xyz = static_cast<float*>(points->GetVoidPointer(0));
  // The voxels each point stands for, when some stand for more than one (to say so at a pick).
  const bool coarser = std::any_of(blocks.begin(), blocks.end(),
                                   [](const MapViewBlock* b) { return !b->voxels.empty(); });
  auto voxels = vtkSmartPointer<vtkUnsignedIntArray>::New();
  voxels->SetName(kVoxelsArray);
  voxels->SetNumberOfValues(coarser ? n : 0);
  vtkIdType i = 0;
  forEachDrawn(blocks, region, layer.stride, [&](const MapViewBlock& b, std::size_t k) {
    const Eigen::Vector3f& p = b.points[k];
    xyz[0] = p.x();
    xyz[1] = p.y();
    xyz[2] = p.z();
    xyz += 3;
    if (coarser) {
      voxels->SetValue(i++, static_cast<unsigned int>(b.voxelsAt(k)));
    }
  });
  layer.poly = vtkSmartPointer<vtkPolyData>::New();
  layer.poly->SetPoints(points);
  if (coarser) {
    layer.poly->GetPointData()->AddArray(voxels);
  }
  layer.poly->SetVerts(pointCells(n, false));
  layer.colours = layerColours(blocks, region, layer.stride, by);
  layer.poly->GetPointData()->SetScalars(layer.colours.scalars);
  return layer;
}

PreparedLayer prepareMesh(const MeshData& mesh, const Eigen::AlignedBox3d* region, ColourBy by) {
  const std::vector<Eigen::Vector3f>& vertices = mesh.vertices.points;
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(static_cast<vtkIdType>(vertices.size()));
  auto* xyz = static_cast<float*>(points->GetVoidPointer(0));
  for (const Eigen::Vector3f& v : vertices) {
    std::copy(v.data(), v.data() + 3, xyz);
    xyz += 3;
  }
  // A triangle is drawn when its centre lies in the region.
  auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
  offsets->InsertNextValue(0);
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3f centre = (vertices[t[0]] + vertices[t[1]] + vertices[t[2]]) / 3.0f;
    if (region == nullptr || region->contains(centre.cast<double>())) {
      for (std::uint32_t v : t) {
        connectivity->InsertNextValue(v);
      }
      offsets->InsertNextValue(connectivity->GetNumberOfValues());
    }
  }
  auto triangles = vtkSmartPointer<vtkCellArray>::New();
  triangles->SetData(offsets, connectivity);
  PreparedLayer layer;
  layer.poly = vtkSmartPointer<vtkPolyData>::New();
  layer.poly->SetPoints(points);
  layer.poly->SetPolys(triangles);
  if (mesh.normals.size() == vertices.size()) {
    auto normals = vtkSmartPointer<vtkFloatArray>::New();
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(static_cast<vtkIdType>(mesh.normals.size()));
    float* n = normals->GetPointer(0);
    for (const Eigen::Vector3f& normal : mesh.normals) {
      std::copy(normal.data(), normal.data() + 3, n);
      n += 3;
    }
    layer.poly->GetPointData()->SetNormals(normals);
  }
  // The region drops triangles, not vertices: every vertex keeps its value.
  layer.colours = layerColours({&mesh.vertices}, nullptr, 1, by);
  layer.poly->GetPointData()->SetScalars(layer.colours.scalars);
  return layer;
}

}  // namespace sonarcarve::widgets
