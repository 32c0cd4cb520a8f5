// The rays through which seabed-aware carving predicts a seabed's image (carve/seabed_model.h)
// and fits its relief (carve/seabed_field_fit.h): some of a frame's beams, each cut into
// elevation intervals over the beam's traced pattern, and how an interval's return is spread
// over the range bins.
#pragma once

#include <Eigen/Geometry>
#include <functional>
#include <vector>

#include "carve/seabed_heightfield.h"
#include "common/thread_pool.h"
#include "sonar/sonar_model.h"

namespace sonarcarve::seabed_internal {

/// The unit ray of a beam at an elevation (up positive) in the sonar frame (x forward, y
/// starboard, z down).
Eigen::Vector3d rayDirection(double elevation_rad, double bearing_rad);

/// Runs fn(i) for i in [0, count), on `pool` where given.
void forEachBeam(ThreadPool* pool, std::size_t count, const std::function<void(std::size_t)>& fn);

/// The rays of some of a frame's beams, in the world, cut into elevation intervals over the
/// beam's traced pattern (to the second null): each interval's two ends and its centre, and
/// its weight (power x solid angle, cos(incidence) still to come).
struct BeamRays {
  std::vector<int> beams;
  int intervals = 0;
  std::vector<Eigen::Vector3d> ends;     // per beam intervals + 1
  std::vector<Eigen::Vector3d> centres;  // per beam intervals
  std::vector<double> weights;           // per interval
};

/// Every `beam_stride`-th beam, intervals of at most `step` rad, rotated by R into the world.
BeamRays beamRays(const SonarModel& sonar, const Eigen::Matrix3d& R, int beam_stride, double step,
                  ThreadPool* pool);

/// Adds `weight` to `column` (one value per range bin) spread evenly over the ranges between
/// r0 and r1, as a surface spreads its return between two rays.
void depositInterval(std::vector<float>& column, double r0, double r1, double weight,
                     const RangeBins& bins);

/// One elevation interval of a beam over a surface: the ranges of its ends (the centre's where
/// an end misses the surface: `own0`, `own1` false), its weight times cos(incidence) there, and
/// the point where its centre meets the surface.
struct SurfaceInterval {
  std::size_t k = 0;  ///< the interval's index in the beam
  double r0 = 0.0, r1 = 0.0, weight = 0.0;
  bool own0 = false, own1 = false;
  Eigen::Vector3d centre_hit = Eigen::Vector3d::Zero();
};

/// The intervals of beam i of `rays` from `position` that meet `surface` facing the ray, given
/// the ranges of its interval ends (`end_ranges`, intervals + 1 of them, +inf where they miss).
std::vector<SurfaceInterval> surfaceIntervals(const BeamRays& rays, std::size_t i,
                                              const SeabedSurface& surface,
                                              const Eigen::Vector3d& position,
                                              const std::vector<double>& end_ranges);

/// Adds beam i of `rays` seen from `position` over `surface` to `column`: each interval's
/// weight times cos(incidence) on the surface, spread between the ranges of its ends.
void accumulateOnSurface(std::vector<float>& column, const BeamRays& rays, std::size_t i,
                         const SeabedSurface& surface, const Eigen::Vector3d& position,
                         const RangeBins& bins);

}  // namespace sonarcarve::seabed_internal
