#include "sim/scene_io.h"

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkFloatArray.h>
#include <vtkOBJReader.h>
#include <vtkPLYReader.h>
#include <vtkPLYWriter.h>
#include <vtkPointData.h>
#include <vtkSTLReader.h>
#include <algorithm>

#include "common/error.h"
#include "io/atomic_file.h"
#include "io/ply_check.h"
#include "sim/vtk_mesh.h"

namespace sonarcarve {
namespace {

// Collects VTK's error events from one algorithm instead of letting VTK print them.
class VtkErrorCatcher {
 public:
  explicit VtkErrorCatcher(vtkAlgorithm* algorithm) {
    callback_ = vtkSmartPointer<vtkCallbackCommand>::New();
    callback_->SetClientData(this);
    callback_->SetCallback([](vtkObject*, unsigned long, void* self, void* data) {
      auto* catcher = static_cast<VtkErrorCatcher*>(self);
      if (catcher->message_.empty() && data != nullptr) {
        catcher->message_ = static_cast<const char*>(data);
      }
    });
    algorithm->AddObserver(vtkCommand::ErrorEvent, callback_);
    algorithm->AddObserver(vtkCommand::WarningEvent, callback_);
  }
  const std::string& message() const { return message_; }

 private:
  vtkSmartPointer<vtkCallbackCommand> callback_;
  std::string message_;
};

std::string lowerExtension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace

Scene loadSceneMesh(const std::filesystem::path& path, float reflectivity) {
  const std::string file = path.string();
  if (!std::filesystem::is_regular_file(path)) {
    throw Error(file, "", "scene mesh not found");
  }
  if (std::filesystem::file_size(path) == 0) {
    throw Error(file, "byte 0", "empty file: expected an STL, OBJ or PLY mesh");
  }
  const std::string ext = lowerExtension(path);
  vtkSmartPointer<vtkAlgorithm> reader;
  if (ext == ".stl") {
    auto r = vtkSmartPointer<vtkSTLReader>::New();
    r->SetFileName(file.c_str());
    reader = r;
  } else if (ext == ".obj") {
    auto r = vtkSmartPointer<vtkOBJReader>::New();
    r->SetFileName(file.c_str());
    reader = r;
  } else if (ext == ".ply") {
    checkPlyFile(path);
    auto r = vtkSmartPointer<vtkPLYReader>::New();
    r->SetFileName(file.c_str());
    reader = r;
  } else {
    throw Error(file, "", "unknown mesh type '" + ext + "': expected .stl, .obj or .ply");
  }
  VtkErrorCatcher errors(reader);
  reader->Update();
  auto* poly = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
  if (!errors.message().empty() && (poly == nullptr || poly->GetNumberOfCells() == 0)) {
    throw Error(file, "", "cannot read mesh: " + errors.message());
  }
  if (poly == nullptr || poly->GetNumberOfPolys() == 0) {
    throw Error(file, "", "no triangles in the mesh (corrupt, truncated or empty?)");
  }
  Scene scene = sceneFromPolyData(poly, reflectivity, path.stem().string());
  scene.target = scene.boundingBoxTarget();
  return scene;
}

void writeScenePly(const Scene& scene, const std::filesystem::path& path) {
  auto poly = polyDataFromScene(scene);
  replaceFileAtomically(path, [&](const std::filesystem::path& tmp) {
    auto writer = vtkSmartPointer<vtkPLYWriter>::New();
    writer->SetFileName(tmp.string().c_str());
    writer->SetInputData(poly);
    writer->SetFileTypeToBinary();
    if (writer->Write() != 1) {
      throw Error(path.string(), "", "PLY writer failed");
    }
  });
}

void writePointsPly(const std::vector<Eigen::Vector3f>& points, const std::filesystem::path& path,
                    const std::vector<float>& scalars, const char* scalar_name) {
  auto vtk_points = vtkSmartPointer<vtkPoints>::New();
  vtk_points->SetDataTypeToFloat();
  vtk_points->SetNumberOfPoints(static_cast<vtkIdType>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) {
    vtk_points->SetPoint(static_cast<vtkIdType>(i), points[i].x(), points[i].y(), points[i].z());
  }
  // vtkPLYWriter writes the points as vertices and only polygons as faces: no cells needed.
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(vtk_points);
  if (!scalars.empty()) {
    auto array = vtkSmartPointer<vtkFloatArray>::New();
    array->SetName(scalar_name);
    array->SetNumberOfValues(static_cast<vtkIdType>(scalars.size()));
    for (std::size_t i = 0; i < scalars.size(); ++i) {
      array->SetValue(static_cast<vtkIdType>(i), scalars[i]);
    }
    poly->GetPointData()->AddArray(array);
  }
  replaceFileAtomically(path, [&](const std::filesystem::path& tmp) {
    auto writer = vtkSmartPointer<vtkPLYWriter>::New();
    writer->SetFileName(tmp.string().c_str());
    writer->SetInputData(poly);
    writer->SetFileTypeToBinary();
    if (!scalars.empty()) {
      writer->SetArrayName(scalar_name);
    }
    if (writer->Write() != 1) {
      throw Error(path.string(), "", "PLY writer failed");
    }
  });
}

std::vector<Eigen::Vector3f> readPointsPly(const std::filesystem::path& path) {
  const std::string file = path.string();
  if (!std::filesystem::is_regular_file(path)) {
    throw Error(file, "", "point cloud not found");
  }
  checkPlyFile(path);
  auto reader = vtkSmartPointer<vtkPLYReader>::New();
  reader->SetFileName(file.c_str());
  VtkErrorCatcher errors(reader);
  reader->Update();
  vtkPolyData* poly = reader->GetOutput();
  if (!errors.message().empty() || poly == nullptr || poly->GetNumberOfPoints() == 0) {
    throw Error(
        file, "",
        "cannot read points from PLY" +
            (errors.message().empty() ? std::string(" (no vertices)") : ": " + errors.message()));
  }
  std::vector<Eigen::Vector3f> points(static_cast<std::size_t>(poly->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i) {
    double p[3];
    poly->GetPoint(i, p);
    points[static_cast<std::size_t>(i)] = Eigen::Vector3d(p[0], p[1], p[2]).cast<float>();
  }
  return points;
}

}  // namespace sonarcarve
