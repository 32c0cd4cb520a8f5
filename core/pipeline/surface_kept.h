// Whether the run kept what a first carve kept: the beam check's first surface (carved inside
// the aperture from the middle of the mission, pipeline/beam_check.h) against the run's
// surface. A first surface holds ghosts (points no structure stands at, from few views) that
// the whole run carves: on missions carved as declared, 55 to 80 % of its points have a run's
// surface point near them (every one within two voxels, some up to four along an axis: the same
// or a neighbouring cell of a grid of two voxels). A run that keeps far less than that has carved
// away a surface its own frames show (a beam weaker than declared, a keep level too high,
// navigation that disagrees between passes) and says so rather than end quietly with a thin map.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "pipeline/run_choice.h"

namespace sonarcarve {

/// A first surface carved from fewer frames is mostly ghosts (16 frames of the riser: 11 % of
/// it kept by a run as declared) and is not a measure.
inline constexpr std::size_t kFirstSurfaceMinFrames = 24;
/// Under this share of the first surface kept, the run warns.
inline constexpr double kKeptFirstSurfaceShare = 0.25;

struct FirstSurfaceKept {
  std::size_t first_points = 0;  ///< the first surface's points looked at
  std::size_t kept = 0;          ///< of those, with a run's surface point near them
  double share() const {
    return first_points == 0 ? 1.0 : static_cast<double>(kept) / static_cast<double>(first_points);
  }
};

/// Counts the points of `first` with a point of `surface` in the same or a neighbouring cell of a
/// grid of 2 `voxel_m`: every surface point within 2 voxels is found, some up to 4 along an axis.
FirstSurfaceKept firstSurfaceKept(const std::vector<Eigen::Vector3f>& first,
                                  const std::vector<Eigen::Vector3f>& surface, double voxel_m);

/// The run's choice "first surface kept".
RunChoice firstSurfaceKeptChoice(const FirstSurfaceKept& kept);

}  // namespace sonarcarve
