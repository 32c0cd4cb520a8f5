// Sizes a reconstruction derives from its parameters and the frames' poses, checked against
// the documented limits (common/input_limits.h) before the map or any buffer is allocated.
#pragma once

#include <Eigen/Geometry>

#include "carve/carve_params.h"
#include "sonar/sonar_model.h"

namespace sonarcarve {

/// Throws Error naming the parameter to change when the map's box (`bounds`, NED metres) holds
/// more than kMaxMapVoxels voxels at carve.voxel_size_m, or when a frame's occlusion buffer
/// (beams x elevation steps over the aperture) exceeds kMaxFramePixels cells.
void requireBoundedSizes(const Eigen::AlignedBox3d& bounds, const SonarModel& sonar,
                         const CarveParams& carve);

}  // namespace sonarcarve
