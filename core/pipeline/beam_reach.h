// How far off the axis carving may trust a dark pixel: the elevation beam's reach, read from
// the frames. Beam-aware carving trusts a dark pixel out to the declared beam's first null
// (+-22.6 degrees for a 20 degree sinc^2 beam). Where the real beam is cut short of it (a spec
// sheet's pattern is a prior, not a fact), a surface seen past the cut returns nothing, its
// pixel bounds it under the keep level, and every surface the tails sweep is carved away: a
// beam cut to nothing past its -6 dB points (+-13.6 degrees) declared sinc^2 gave the riser an
// empty map.
//
// The check follows the points of a first surface (carved inside the aperture) through the
// mission's views and asks, band of elevation by band, what share of the points still standing
// that a view sees in the band the band carves (their hazard). A beam as declared carves a
// small share in every band (ghosts of the first surface: at most 3 % a half degree on the
// riser's pass, as declared, sinc^2 or gaussian); a cut beam carves most of what its tails
// see past the cut (12 to 69 % a half degree from 0.4 degree past it). Views that cannot
// know what hides a point (the check has no occlusion) carve more in an orbit: up to 9.5 %.
// The reach is the inner edge of the first band whose hazard exceeds kCliffHazard, moved in
// over the bands just inside it whose hazard exceeds kCliffOnset (the cut shows a band or two
// early: a point's first view past the cut lies up to a view's spacing past it), and only
// where a plateau of bands that carve little lies inside it.
#pragma once

#include <Eigen/Geometry>
#include <cstddef>
#include <functional>
#include <limits>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "pipeline/frame_stage.h"
#include "pipeline/run_choice.h"
#include "sonar/sonar_model.h"

namespace sonarcarve {

/// The bands' width, radians (half a degree).
inline constexpr double kReachBandRad = 0.5 * 3.14159265358979323846 / 180.0;
/// A band whose views carve more than this share of the points they see marks the beam's end;
/// the bands just inside it that carve more than kCliffOnset are its start.
inline constexpr double kCliffHazard = 0.15;
inline constexpr double kCliffOnset = 0.075;
/// The bands just inside the end that must carve little (the tails working there); a mission
/// whose views carve many points everywhere (a first surface of ghosts, from a short
/// mission: 18 to 50 % a band on 16 frames of the riser, whose tails then carve them) is left
/// as declared.
inline constexpr std::size_t kReachPlateauBands = 2;
/// A band needs this many points seen in it, still standing, to tell.
inline constexpr std::size_t kReachMinAtRisk = 100;

/// What the views do to one point of the first surface, elevations as |angles| off the axis.
struct PointFate {
  /// The smallest elevation at which a view carves it (its bound at or under the keep level).
  double carved_at = std::numeric_limits<double>::infinity();
  double widest_view = 0.0;  ///< the widest elevation a view sees it at
};

struct ReachBand {
  double lo_rad = 0.0;
  std::size_t at_risk = 0;  ///< points standing at lo, seen past it
  std::size_t carved = 0;   ///< of those, carved in the band
  double hazard() const {
    return at_risk == 0 ? 0.0 : static_cast<double>(carved) / static_cast<double>(at_risk);
  }
};

struct ElevationReach {
  double reach_rad = 0.0;  ///< the first null where the beam is as declared
  double first_null_rad = 0.0;
  std::vector<ReachBand> bands;  ///< from the aperture's edge to the first null
  bool shortened() const { return reach_rad < first_null_rad; }
};

/// Each point's fate through the views `frames`, whose images (as carving reads them, power)
/// `image(i)` gives (nullopt: left out): a view carves a point where its pixel (or, dark, the
/// sonar's dark level) over the declared sinc^2 beam's power there is at or under
/// `keep_level`, as beam-aware carving does, out to the first null.
std::vector<PointFate> followPoints(const std::vector<Eigen::Vector3f>& points_world,
                                    const std::vector<PosedFrame>& frames,
                                    const std::function<std::optional<cv::Mat>(std::size_t)>& image,
                                    const SonarModel& sonar, double keep_level);

/// The reach from the points' fates, between +-aperture/2 and the declared first null.
ElevationReach reachFromFates(const std::vector<PointFate>& fates, double aperture_half_rad,
                              double first_null_rad);

/// The run's choice "elevation beam reach", for an analyst.
RunChoice elevationReachChoice(const ElevationReach& reach);

}  // namespace sonarcarve
