#include "geometry/scene_io.h"

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
#include "geometry/internal/vtk_mesh.h"
#include "io/atomic_file.h"
#include "io/ply_check.h"
#include "io/point_cloud_ply.h"

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
  PointCloud cloud;
  cloud.positions = points;
  if (!scalars.empty()) {
    cloud.properties[scalar_name] = scalars;
  }
  writePointCloudPly(path, cloud);
}

std::vector<Eigen::Vector3f> readPointsPly(const std::filesystem::path& path) {
  return readPointCloudPly(path).positions;
}

}  // namespace sonarcarve
