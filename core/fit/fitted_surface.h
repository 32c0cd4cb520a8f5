// The surface of a fitted map as the run's surface points: where each ray of each frame,
// within the beam's -3 dB aperture, becomes more likely stopped than not (its transmittance
// falls through 1/2), at that point of the ray. A voxel holding such points in at least
// `min_views` frames is a surface point, at the mean of its crossings (finer than the voxel),
// with its fitted reflectance as intensity and the frames as views.
#pragma once

#include <cstdint>
#include <vector>

#include "common/progress.h"
#include "common/thread_pool.h"
#include "fit/map_fit.h"
#include "model/block_grid.h"
#include "occlusion/surface_points.h"
#include "sonar/sonar_model.h"

namespace sonarcarve {

/// Throws Cancelled when `progress` is cancelled.
SurfacePoints fittedSurface(const BlockGrid& grid, const SonarModel& sonar,
                            const std::vector<MapFitFrame>& frames, const MapFitParams& params,
                            std::uint32_t min_views, ThreadPool& pool, Progress& progress);

}  // namespace sonarcarve
