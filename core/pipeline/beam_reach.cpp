#include "pipeline/beam_reach.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "common/angles.h"
#include "sonar/beam_pattern.h"

namespace sonarcarve {

std::vector<PointFate> followPoints(const std::vector<Eigen::Vector3f>& points_world,
                                    const std::vector<PosedFrame>& frames,
                                    const std::function<std::optional<cv::Mat>(std::size_t)>& image,
                                    const SonarModel& sonar, double keep_level) {
  const SincSquaredBeam beam(sonar.verticalAperture());
  const double first_null = beam.null(1);
  const double dark = sonar.intensityScale().darkPower();
  std::vector<PointFate> fates(points_world.size());
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const std::optional<cv::Mat> pixels = image(f);
    if (!pixels) {
      continue;
    }
    const Eigen::Isometry3d T_sonar_world = frames[f].T_world_sonar.inverse();
    for (std::size_t p = 0; p < points_world.size(); ++p) {
      const Polar polar = polarFromPoint(T_sonar_world * points_world[p].cast<double>());
      const std::optional<int> bin = sonar.range().binOf(polar.range_m);
      const std::optional<int> column = sonar.bearings().beamOf(polar.bearing_rad);
      const double elevation = std::abs(polar.elevation_rad);
      if (!bin || !column || elevation > first_null) {
        continue;
      }
      PointFate& fate = fates[p];
      fate.widest_view = std::max(fate.widest_view, elevation);
      const double value = pixels->at<float>(*bin, *column);
      const double bound = (value > 0.0 ? value : dark) / std::max(beam.power(elevation), 1e-6);
      if (bound <= keep_level) {
        fate.carved_at = std::min(fate.carved_at, elevation);
      }
    }
  }
  return fates;
}

ElevationReach reachFromFates(const std::vector<PointFate>& fates, double aperture_half_rad,
                              double first_null_rad) {
  ElevationReach reach;
  reach.first_null_rad = first_null_rad;
  reach.reach_rad = first_null_rad;
  const auto count = static_cast<std::size_t>(
      std::ceil((first_null_rad - aperture_half_rad) / kReachBandRad - 1e-9));
  for (std::size_t b = 0; b < count; ++b) {
    ReachBand band;
    band.lo_rad = aperture_half_rad + static_cast<double>(b) * kReachBandRad;
    const double hi = band.lo_rad + kReachBandRad;
    for (const PointFate& fate : fates) {
      if (fate.carved_at > band.lo_rad && fate.widest_view > band.lo_rad) {
        ++band.at_risk;
        band.carved += fate.carved_at <= hi ? 1 : 0;
      }
    }
    reach.bands.push_back(band);
  }
  const auto tells = [](const ReachBand& band, double hazard) {
    return band.at_risk >= kReachMinAtRisk && band.hazard() > hazard;
  };
  for (std::size_t b = 0; b < reach.bands.size(); ++b) {
    if (tells(reach.bands[b], kCliffHazard)) {
      std::size_t start = b;
      while (start > 0 && tells(reach.bands[start - 1], kCliffOnset)) {
        --start;
      }
      // The tails worked inside the cut: a plateau of bands that carve little. Without one
      // the views carve many points at every elevation (a first surface of ghosts, from a
      // short mission, which the tails are there to carve).
      const bool plateau =
          start >= kReachPlateauBands &&
          std::all_of(reach.bands.begin() + static_cast<std::ptrdiff_t>(start - kReachPlateauBands),
                      reach.bands.begin() + static_cast<std::ptrdiff_t>(start),
                      [](const ReachBand& inside) {
                        return inside.at_risk >= kReachMinAtRisk && inside.hazard() <= kCliffOnset;
                      });
      if (plateau) {
        reach.reach_rad = reach.bands[start].lo_rad;
      }
      break;
    }
  }
  return reach;
}

RunChoice elevationReachChoice(const ElevationReach& reach) {
  std::string bands;
  for (const ReachBand& band : reach.bands) {
    char one[64];
    std::snprintf(one, sizeof one, "%s%.1f: %zu of %zu", bands.empty() ? "" : ", ",
                  radToDeg(band.lo_rad), band.carved, band.at_risk);
    bands += one;
  }
  RunChoice choice;
  choice.name = "elevation beam reach";
  char head[200];
  std::snprintf(head, sizeof head,
                "points of a first surface carved in each half degree off the axis, of those "
                "still standing that the views see there (the beam ends where over %.0f %% are): ",
                100.0 * kCliffHazard);
  choice.detail = head + bands;
  char value[64];
  std::snprintf(value, sizeof value, "%.1f degrees", radToDeg(reach.reach_rad));
  choice.value = value;
  if (reach.shortened()) {
    char reason[240];
    std::snprintf(reason, sizeof reason,
                  "the views carve most of the surface they see past %.1f degrees, inside the "
                  "declared beam's first null (%.1f degrees): the beam ends there, shorter than "
                  "declared; carving stops there",
                  radToDeg(reach.reach_rad), radToDeg(reach.first_null_rad));
    choice.reason = reason;
    choice.action = "check the sonar's elevation beam pattern: its tails are weaker than declared";
    choice.warning = true;
  } else {
    choice.reason =
        "the views past the aperture carve no more of the surface than ghosts: the "
        "declared beam's first null";
  }
  return choice;
}

}  // namespace sonarcarve
