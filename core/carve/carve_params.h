// Parameters of space carving, with the seed paper's defaults. SI units; YAML in degrees.
#pragma once

#include <algorithm>

#include <Eigen/Geometry>
#include <memory>
#include <optional>

#include "common/angles.h"

namespace sonarcarve {

class SeabedHeightfield;  // carve/seabed_heightfield.h

struct CarveParams {
  static constexpr double kDefaultVoxelSize_m = 0.02;
  static constexpr double kDefaultElevationStep_rad = degToRad(0.2);

  double voxel_size_m = kDefaultVoxelSize_m;
  /// Pixels at or below this intensity count as empty water and carve their arcs.
  double intensity_threshold = 0.0;
  /// Elevation step of the paper's arcs (reference engine) and of occlusion resolution.
  double elevation_step_rad = kDefaultElevationStep_rad;
  /// Range window used, metres; 0 means the sonar's own limit.
  double range_min_m = 0.0;
  double range_max_m = 0.0;
  /// Only this box of the world (NED, metres) is mapped; unset: everything the frames see.
  std::optional<Eigen::AlignedBox3d> region;

  /// Beam-aware carving (fast engine; docs/reconstruction.md). The engine assumes
  /// the sinc^2 elevation beam of sonar/beam_pattern.h (-3 dB at +-aperture/2) and carves
  /// over its whole main lobe, to the first null: a pixel of intensity I bounds what a return
  /// at elevation theta would give on the beam's axis by I / p(theta), and a voxel is carved
  /// once any view bounds it at or below `keep_level`. Off: the seed paper's rule, over
  /// +-aperture/2 with no weighting.
  bool beam_aware = true;
  /// Beam-aware: returns more than this far below the mission's bright returns are not kept
  /// (the pipeline sets keep_level from it); dB.
  double dynamic_range_db = 20.0;
  /// Beam-aware: a voxel whose on-axis bound is at or below this is carved (counts).
  double keep_level = 0.0;
  /// What a dark pixel (zero after the threshold) says. Exact: nothing returned there (an
  /// image without noise, no detector), so it carves across the main lobe. BelowDetection: a
  /// detector took it for background; a return may have been as strong as its detection
  /// level, so it carves only inside +-aperture/2, where the beam keeps half its power.
  enum class DarkPixels { Exact, BelowDetection };
  DarkPixels dark_pixels = DarkPixels::BelowDetection;
  /// Exact dark pixels hold under this power: half a count on the sonar's intensity scale
  /// (IntensityScale::darkPower; the pipeline sets it; 0.5 for linear counts).
  double dark_pixel_level = 0.5;
  /// Robust carving (fast engine): a voxel is carved once this many views
  /// have found it empty; 1 is the seed paper's rule (one view of empty water carves). More
  /// votes tolerate views placed a little off by their navigation; they carve ghosts and
  /// noise later.
  int carve_votes = 1;
  /// Shadow-aware carving (fast engine): a frame carves a voxel only if no pixel nearer on
  /// the voxel's own ray (beam and elevation) may hold a surface that hides it (lit, bounding
  /// a return above the keep level there, on a voxel not carved, and behind a detector kept
  /// by some view; carve/shadow_limit.h). Off: the seed paper's rule, where a structure's
  /// shadow carves whatever lies in it. A run sets it (pipeline/shadow_carving.h).
  bool shadow_aware = false;
  /// Seabed-aware carving (fast engine, beam-aware): each frame fits a plane to the seabed it
  /// images through the whole beam pattern (carve/seabed_model.h) and, where one explains it,
  /// bounds the other voxels on each arc by what the seabed leaves of the pixel, keeps the
  /// seabed's band where the pixel is lit and leaves what lies under it. Off: a flat seabed
  /// fills the main lobe at every range and the water over it is never carved.
  bool seabed_aware = true;
  /// Seabed-aware: the seabed's relief fitted over the mission (carve/seabed_field_fit.h), used
  /// in place of each frame's plane where it is known; null: the planes alone.
  std::shared_ptr<const SeabedHeightfield> seabed_field;
};

/// The keep level a frame carves with. With exact dark pixels (whole counts, no detector) it
/// is at least what a dark pixel bounds at the -3 dB edge of the aperture (half a count over
/// half the beam's power: 1 count of a linear sonar), so that a dark pixel always carves inside
/// +-aperture/2, as
/// in the seed paper: a mission whose bright returns are only a few tens of counts would
/// otherwise keep returns under one count, which its images cannot show, and carve nothing.
inline double effectiveKeepLevel(const CarveParams& params) {
  if (params.dark_pixels != CarveParams::DarkPixels::Exact) {
    return params.keep_level;
  }
  constexpr double kGainAtApertureEdge = 0.5;  // -3 dB
  return std::max(params.keep_level, params.dark_pixel_level / kGainAtApertureEdge);
}

/// Sets `params` as a run carves: the keep level `measured` (from the mission's bright returns),
/// what a dark pixel means (exact, no detector ran; or below detection) and the sonar's dark
/// power, then the keep level raised as effectiveKeepLevel says.
inline void setKeepLevel(CarveParams& params, double measured, bool dark_is_exact,
                         double dark_power) {
  params.keep_level = measured;
  params.dark_pixels =
      dark_is_exact ? CarveParams::DarkPixels::Exact : CarveParams::DarkPixels::BelowDetection;
  params.dark_pixel_level = dark_power;
  params.keep_level = effectiveKeepLevel(params);
}

/// Whether a map carved with `params` keeps each voxel's view and vote counts (2 bytes a
/// voxel more in every block that holds values).
inline bool keepsViewCounts(const CarveParams& params) {
  return params.carve_votes > 1;
}

}  // namespace sonarcarve
