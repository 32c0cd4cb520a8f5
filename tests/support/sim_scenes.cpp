#include "support/sim_scenes.h"

#include <vtkPlaneSource.h>
#include <vtkSphereSource.h>
#include <Eigen/Geometry>

#include "geometry/internal/vtk_mesh.h"

namespace sonarcarve::test {

Scene plate(const Eigen::Vector3d& centre, const Eigen::Vector3d& normal, double size,
            float reflectivity) {
  const Eigen::Vector3d n = normal.normalized();
  // Two in-plane axes: one horizontal (unless the plate is horizontal), one completing them.
  Eigen::Vector3d u = n.cross(Eigen::Vector3d::UnitZ());
  if (u.norm() < 1e-6) {
    u = Eigen::Vector3d::UnitX();
  }
  u.normalize();
  const Eigen::Vector3d v = n.cross(u).normalized();
  Eigen::Vector3d origin = centre - 0.5 * size * (u + v);
  Eigen::Vector3d p1 = origin + size * u;
  Eigen::Vector3d p2 = origin + size * v;
  auto source = vtkSmartPointer<vtkPlaneSource>::New();
  source->SetOrigin(origin.data());
  source->SetPoint1(p1.data());
  source->SetPoint2(p2.data());
  source->Update();
  return sceneFromPolyData(source->GetOutput(), reflectivity, "plate");
}

Scene sphereScene(const std::vector<std::pair<Eigen::Vector3d, double>>& spheres) {
  Scene scene;
  scene.name = "spheres";
  for (const auto& [centre, radius] : spheres) {
    auto source = vtkSmartPointer<vtkSphereSource>::New();
    source->SetCenter(centre.data());
    source->SetRadius(radius);
    source->SetThetaResolution(48);
    source->SetPhiResolution(24);
    source->Update();
    scene.append(sceneFromPolyData(source->GetOutput(), 0.8f, "sphere"));
  }
  return scene;
}

}  // namespace sonarcarve::test
