// Where a 3D view's camera is, to save and restore a view (world NED, metres): what the
// workbench's map view holds and what a session file keeps.
#pragma once

#include <Eigen/Core>

namespace sonarcarve {

struct CameraState {
  Eigen::Vector3d position{0, 0, 0};
  Eigen::Vector3d focal_point{0, 0, 0};
  Eigen::Vector3d view_up{0, 0, -1};
  bool parallel = false;
  double parallel_scale = 1.0;
  double view_angle_deg = 30.0;
};

}  // namespace sonarcarve
