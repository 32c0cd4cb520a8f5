#include "occlusion/surface_points.h"

#include "geo/crs.h"
#include "io/mesh/point_cloud_ply.h"
#include "sonar/mission_origin.h"

namespace sonarcarve {

std::vector<Eigen::Vector3f> positionsOf(const SurfacePoints& points) {
  std::vector<Eigen::Vector3f> positions;
  positions.reserve(points.size());
  for (const SurfacePoint& p : points) {
    positions.push_back(p.position_m);
  }
  return positions;
}

void writeSurfacePointsPly(const SurfacePoints& points, const std::filesystem::path& path,
                           const Eigen::Vector3d& origin_ned_m, const std::string& crs) {
  PointCloud cloud;
  if (!origin_ned_m.isZero()) {
    cloud.comments.push_back(originComment(origin_ned_m));
  }
  if (!crs.empty()) {
    cloud.comments.push_back(crsComment(crs));
  }
  std::vector<float>& intensity = cloud.properties["intensity"];
  std::vector<std::uint32_t> views;
  for (const SurfacePoint& p : points) {
    cloud.positions.push_back(p.position_m);
    intensity.push_back(p.intensity);
    views.push_back(p.views);
  }
  writePointCloudPly(path, cloud, {{"views", views}});
}

SurfacePoints readSurfacePointsPly(const std::filesystem::path& path) {
  const PointCloud cloud = readPointCloudPly(path);
  const auto intensity = cloud.properties.find("intensity");
  const auto views = cloud.properties.find("views");
  SurfacePoints points(cloud.positions.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    points[i].position_m = cloud.positions[i];
    points[i].intensity = intensity != cloud.properties.end() ? intensity->second[i] : 0.0f;
    points[i].views =
        views != cloud.properties.end() ? static_cast<std::uint32_t>(views->second[i]) : 0u;
  }
  return points;
}

}  // namespace sonarcarve
