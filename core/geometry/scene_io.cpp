#include "geometry/scene_io.h"

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSTLReader.h>
#include <algorithm>

#include "common/available_memory.h"
#include "common/error.h"
#include "geometry/internal/vtk_mesh.h"
#include "io/files/input_file.h"
#include "io/mesh/obj_mesh.h"
#include "io/mesh/point_cloud_ply.h"
#include "io/mesh/stl_check.h"

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

// A mesh whose triangles have no area: every one's corners on one point or line, as a file of
// zeros (a sparse or zero-filled file) reads. Evaluated against, it gave an accuracy of "inf m"
// with exit 0; simulated, frames of nothing.
Error noSurface(const std::string& file, std::size_t triangles) {
  return Error(file, "",
               std::to_string(triangles) +
                   " triangles, none of which has an area (the corners of each on one point or "
                   "line, as in a file of zeros): expected a surface");
}

}  // namespace

namespace {

// STL through VTK's reader (an STL has no vertex indices to get wrong; its coordinates are
// checked after).
vtkSmartPointer<vtkPolyData> readStl(const std::filesystem::path& path) {
  const std::string file = path.string();
  const std::optional<std::uint32_t> declared = checkStlFile(path);
  auto reader = vtkSmartPointer<vtkSTLReader>::New();
  reader->SetFileName(file.c_str());
  VtkErrorCatcher errors(reader);
  reader->Update();
  vtkSmartPointer<vtkPolyData> poly = reader->GetOutput();
  if (!errors.message().empty() && (poly == nullptr || poly->GetNumberOfCells() == 0)) {
    throw Error(file, "", "cannot read mesh: " + errors.message());
  }
  // VTK leaves out the triangles without an area: those the header declared are the count.
  if (declared && *declared > 0 && (poly == nullptr || poly->GetNumberOfPolys() == 0)) {
    throw noSurface(file, *declared);
  }
  if (poly != nullptr) {
    requireValidPolyData(poly, file);
  }
  return poly;
}

// What reading a mesh may take per byte of its file, at most: an ASCII OBJ vertex ("v 0 0 0",
// 8 bytes) becomes 12 bytes of floats, VTK's 24 of doubles and the scene's copy; a binary STL
// triangle (50 bytes) about 150. Eight bytes a byte covers both with room.
constexpr std::uintmax_t kMeshMemoryPerFileByte = 8;

void requireMemoryToRead(const std::string& file, std::uintmax_t bytes) {
  const std::optional<AvailableMemory> available = availableMemory();
  const std::uintmax_t needed = bytes * kMeshMemoryPerFileByte;
  if (available && needed > available->bytes) {
    throw Error(file, "",
                "a mesh of " + std::to_string(bytes >> 10) + " KiB needs up to " +
                    std::to_string(needed >> 20) + " MiB to read, more than the " +
                    std::to_string(available->bytes >> 20) + " MiB available (" +
                    available->source + "): expected a smaller mesh or more memory");
  }
}

// Moves an STL's points (floats already: the format holds no more) by `offset_m`.
void shiftPolyData(vtkPolyData& poly, const Eigen::Vector3d& offset_m) {
  vtkPoints* points = poly.GetPoints();
  for (vtkIdType i = 0; points != nullptr && i < points->GetNumberOfPoints(); ++i) {
    double p[3];
    points->GetPoint(i, p);
    points->SetPoint(i, p[0] + offset_m.x(), p[1] + offset_m.y(), p[2] + offset_m.z());
  }
}

}  // namespace

Scene loadSceneMesh(const std::filesystem::path& path, float reflectivity,
                    const Eigen::Vector3d& origin_ned_m) {
  const std::string file = path.string();
  requireRegularFile(path, "a mesh: STL, OBJ or PLY");
  const std::uintmax_t bytes = std::filesystem::file_size(path);
  if (bytes == 0) {
    throw Error(file, "byte 0", "empty file: expected an STL, OBJ or PLY mesh");
  }
  requireMemoryToRead(file, bytes);
  const std::string ext = lowerExtension(path);
  vtkSmartPointer<vtkPolyData> poly;
  if (ext == ".stl") {
    poly = readStl(path);
    if (poly != nullptr && !origin_ned_m.isZero()) {
      shiftPolyData(*poly, -origin_ned_m);
    }
  } else if (ext == ".obj") {
    const ObjMesh obj = readObjMesh(path, origin_ned_m);
    poly = triangleMesh(obj.vertices, obj.triangles);
  } else if (ext == ".ply") {
    const PlyMesh ply = readPlyMesh(path, origin_ned_m);
    poly = triangleMesh(ply.vertices.positions, ply.triangles);
  } else {
    throw Error(file, "", "unknown mesh type '" + ext + "': expected .stl, .obj or .ply");
  }
  if (poly == nullptr || poly->GetNumberOfPolys() == 0) {
    throw Error(file, "", "no triangles in the mesh (corrupt, truncated or empty?)");
  }
  Scene scene = sceneFromPolyData(poly, reflectivity, path.stem().string());
  if (!(scene.area() > 0.0)) {
    throw noSurface(file, scene.triangles.size());
  }
  scene.target = scene.boundingBoxTarget();
  return scene;
}

void writeScenePly(const Scene& scene, const std::filesystem::path& path) {
  PointCloud vertices;
  vertices.positions = scene.vertices;
  writePointCloudPly(path, vertices, {}, scene.triangles);
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

std::vector<Eigen::Vector3f> readPointsPly(const std::filesystem::path& path,
                                           const Eigen::Vector3d& origin_ned_m) {
  return readPointCloudPly(path, origin_ned_m).positions;
}

}  // namespace sonarcarve
