#include "view_clip.h"

#include <limits>

namespace sonarcarve::widgets {

Eigen::AlignedBox3d ViewClip::region() const {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  Eigen::AlignedBox3d r(Eigen::Vector3d::Constant(-kInf), Eigen::Vector3d::Constant(kInf));
  if (box) {
    r = r.intersection(*box);
  }
  if (section) {
    const int axis = static_cast<int>(section->axis);
    const double half = section->thickness_m / 2.0;
    r.min()[axis] = std::max(r.min()[axis], section->position_m - half);
    r.max()[axis] = std::min(r.max()[axis], section->position_m + half);
  }
  return r;
}

bool ViewClip::contains(const Eigen::Vector3f& p) const {
  return !active() || region().contains(p.cast<double>());
}

}  // namespace sonarcarve::widgets
