#include "support/sim_scenes.h"

#include <vtkPlaneSource.h>
#include <vtkSphereSource.h>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "geometry/internal/vtk_mesh.h"
#include "sonar/sonar_model.h"

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

Scene sphericalPatch(double range, double bearing_lo, double bearing_hi, double elevation_lo,
                     double elevation_hi, double step_rad, float reflectivity) {
  Scene scene;
  scene.name = "spherical patch";
  const int nb = std::max(1, static_cast<int>(std::ceil((bearing_hi - bearing_lo) / step_rad)));
  const int ne = std::max(1, static_cast<int>(std::ceil((elevation_hi - elevation_lo) / step_rad)));
  for (int i = 0; i <= ne; ++i) {
    for (int j = 0; j <= nb; ++j) {
      const Eigen::Vector3d p =
          pointFromPolar({range, bearing_lo + (bearing_hi - bearing_lo) * j / nb,
                          elevation_lo + (elevation_hi - elevation_lo) * i / ne});
      scene.vertices.push_back(p.cast<float>());
      scene.normals.push_back(-p.normalized().cast<float>());
    }
  }
  const auto at = [&](int i, int j) { return static_cast<std::uint32_t>(i * (nb + 1) + j); };
  for (int i = 0; i < ne; ++i) {
    for (int j = 0; j < nb; ++j) {
      scene.triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
      scene.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
      scene.reflectivity.insert(scene.reflectivity.end(), 2, reflectivity);
    }
  }
  return scene;
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
