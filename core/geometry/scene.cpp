#include "geometry/scene.h"

#include <Eigen/Geometry>
#include <limits>

namespace sonarcarve {

void Scene::append(const Scene& other) {
  const auto offset = static_cast<std::uint32_t>(vertices.size());
  vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
  normals.insert(normals.end(), other.normals.begin(), other.normals.end());
  for (const auto& t : other.triangles) {
    triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  }
  reflectivity.insert(reflectivity.end(), other.reflectivity.begin(), other.reflectivity.end());
}

Eigen::Vector3d Scene::boundsMin() const {
  Eigen::Vector3f m = Eigen::Vector3f::Constant(std::numeric_limits<float>::max());
  for (const auto& v : vertices) {
    m = m.cwiseMin(v);
  }
  return m.cast<double>();
}

Eigen::Vector3d Scene::boundsMax() const {
  Eigen::Vector3f m = Eigen::Vector3f::Constant(std::numeric_limits<float>::lowest());
  for (const auto& v : vertices) {
    m = m.cwiseMax(v);
  }
  return m.cast<double>();
}

double Scene::area() const {
  double total = 0.0;
  for (const auto& t : triangles) {
    const Eigen::Vector3d a = vertices[t[0]].cast<double>();
    total +=
        0.5 * (vertices[t[1]].cast<double>() - a).cross(vertices[t[2]].cast<double>() - a).norm();
  }
  return total;
}

InspectionTarget Scene::boundingBoxTarget() const {
  const Eigen::Vector3d lo = boundsMin();
  const Eigen::Vector3d hi = boundsMax();
  InspectionTarget box_target;
  box_target.axis_point_m = 0.5 * (lo + hi);
  box_target.top_down_m = lo.z();
  box_target.bottom_down_m = hi.z();
  return box_target;
}

}  // namespace sonarcarve
