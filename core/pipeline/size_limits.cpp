#include "pipeline/size_limits.h"

#include <cmath>
#include <sstream>

#include "common/angles.h"
#include "common/error.h"
#include "common/input_limits.h"

namespace sonarcarve {

void requireBoundedSizes(const Eigen::AlignedBox3d& bounds, const SonarModel& sonar,
                         const CarveParams& carve) {
  const Eigen::Vector3d extent_m = bounds.sizes();
  const Eigen::Vector3d per_axis = (extent_m / carve.voxel_size_m).array().ceil() + 1.0;
  const double voxels = per_axis.prod();
  if (!(voxels <= kMaxMapVoxels)) {
    std::ostringstream text;
    text.precision(3);
    text << "the map's box (" << extent_m.x() << " x " << extent_m.y() << " x " << extent_m.z()
         << " m) holds " << voxels << " voxels of " << carve.voxel_size_m << " m: expected at most "
         << kMaxMapVoxels << "; use a larger voxel size or a smaller region";
    throw Error("parameters", "voxel_size_m", text.str());
  }
  const double elevation_steps = std::ceil(sonar.verticalAperture() / carve.elevation_step_rad);
  const double cells = elevation_steps * sonar.cols();
  if (!(cells <= static_cast<double>(kMaxFramePixels))) {
    std::ostringstream text;
    text << "a step of " << radToDeg(carve.elevation_step_rad) << " degrees over the "
         << radToDeg(sonar.verticalAperture()) << " degree aperture and " << sonar.cols()
         << " beams makes " << cells << " occlusion cells per frame: expected at most "
         << kMaxFramePixels << "; use a larger step";
    throw Error("parameters", "elevation_step_deg", text.str());
  }
}

}  // namespace sonarcarve
