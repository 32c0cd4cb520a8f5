#include "geometry/internal/vtk_mesh.h"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkPointData.h>
#include <vtkPolyDataNormals.h>
#include <vtkTriangleFilter.h>

#include "common/error.h"
#include "io/files/finite_points.h"

namespace sonarcarve {

Scene sceneFromPolyData(vtkPolyData* poly, float reflectivity, const std::string& name) {
  auto triangulate = vtkSmartPointer<vtkTriangleFilter>::New();
  triangulate->SetInputData(poly);
  triangulate->PassVertsOff();
  triangulate->PassLinesOff();
  auto normals = vtkSmartPointer<vtkPolyDataNormals>::New();
  normals->SetInputConnection(triangulate->GetOutputPort());
  normals->SetFeatureAngle(50.0);
  normals->SplittingOn();
  normals->ConsistencyOn();
  normals->Update();
  vtkPolyData* out = normals->GetOutput();

  Scene scene;
  scene.name = name;
  const vtkIdType n = out->GetNumberOfPoints();
  vtkDataArray* point_normals = out->GetPointData()->GetNormals();
  scene.vertices.reserve(static_cast<std::size_t>(n));
  scene.normals.reserve(static_cast<std::size_t>(n));
  for (vtkIdType i = 0; i < n; ++i) {
    double p[3];
    out->GetPoint(i, p);
    scene.vertices.emplace_back(static_cast<float>(p[0]), static_cast<float>(p[1]),
                                static_cast<float>(p[2]));
    double nn[3] = {0.0, 0.0, 1.0};
    if (point_normals != nullptr) {
      point_normals->GetTuple(i, nn);
    }
    scene.normals.push_back(Eigen::Vector3f(static_cast<float>(nn[0]), static_cast<float>(nn[1]),
                                            static_cast<float>(nn[2]))
                                .normalized());
  }
  scene.triangles = trianglesOf(out);
  scene.reflectivity.assign(scene.triangles.size(), reflectivity);
  return scene;
}

vtkSmartPointer<vtkPolyData> triangleMesh(
    const std::vector<Eigen::Vector3f>& vertices,
    const std::vector<std::array<std::uint32_t, 3>>& triangles) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(static_cast<vtkIdType>(vertices.size()));
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const auto& v = vertices[i];
    points->SetPoint(static_cast<vtkIdType>(i), v.x(), v.y(), v.z());
  }
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  for (const auto& t : triangles) {
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    cells->InsertNextCell(3, ids);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(cells);
  return poly;
}

vtkSmartPointer<vtkPolyData> polyDataFromScene(const Scene& scene) {
  return triangleMesh(scene.vertices, scene.triangles);
}

std::vector<std::array<std::uint32_t, 3>> trianglesOf(vtkPolyData* poly) {
  std::vector<std::array<std::uint32_t, 3>> triangles;
  auto ids = vtkSmartPointer<vtkIdList>::New();
  vtkCellArray* polys = poly->GetPolys();
  polys->InitTraversal();
  while (polys->GetNextCell(ids)) {
    if (ids->GetNumberOfIds() == 3) {
      triangles.push_back({static_cast<std::uint32_t>(ids->GetId(0)),
                           static_cast<std::uint32_t>(ids->GetId(1)),
                           static_cast<std::uint32_t>(ids->GetId(2))});
    }
  }
  return triangles;
}

// The filters downstream index points by the faces' vertex ids without a check: an id out of
// range would read outside the points, and a NaN vertex would poison every distance.
void requireValidPolyData(vtkPolyData* poly, const std::string& file) {
  const vtkIdType points = poly->GetNumberOfPoints();
  for (vtkIdType i = 0; i < points; ++i) {
    double p[3];
    poly->GetPoint(i, p);
    requireFinitePoint(Eigen::Vector3d(p[0], p[1], p[2]).cast<float>(), file,
                       "vertex " + std::to_string(i));
  }
  auto ids = vtkSmartPointer<vtkIdList>::New();
  vtkCellArray* cells = poly->GetPolys();
  cells->InitTraversal();
  for (vtkIdType face = 0; cells->GetNextCell(ids); ++face) {
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) {
      const vtkIdType id = ids->GetId(k);
      if (id < 0 || id >= points) {
        throw Error(file, "face " + std::to_string(face),
                    "vertex index " + std::to_string(id) + " out of range: expected 0 to " +
                        std::to_string(points - 1));
      }
    }
  }
}

}  // namespace sonarcarve
