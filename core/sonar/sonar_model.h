// SonarModel: the geometry of a 2D imaging sonar (range bins, bearing table, vertical aperture,
// elevation beam pattern), the scale of its counts, and the conversions between a pixel, polar
// coordinates and 3D points in the sonar frame.
//
// Sonar frame (docs/conventions.md): x forward along the boresight, y to starboard, z down.
// Bearing phi is positive to starboard; elevation theta is positive up (towards -z):
//   p = r * (cos(theta) cos(phi), cos(theta) sin(phi), -sin(theta)).
// A pixel (row, col) is range bin `row` (near to far) and beam `col` (port to starboard).
// Units: metres and radians. Immutable after construction; safe to share between threads.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "sonar/beam_pattern.h"
#include "sonar/bearing_table.h"
#include "sonar/intensity_scale.h"
#include "sonar/range_bins.h"

namespace sonarcarve {

struct Polar {
  double range_m = 0.0;
  double bearing_rad = 0.0;
  double elevation_rad = 0.0;
};

struct Pixel {
  int row = 0;  ///< range bin, 0 = nearest
  int col = 0;  ///< beam, 0 = most port
  bool operator==(const Pixel&) const = default;
};

/// Polar coordinates -> point in the sonar frame.
Eigen::Vector3d pointFromPolar(const Polar& polar);
/// Point in the sonar frame -> polar coordinates (range 0 gives bearing 0, elevation 0).
Polar polarFromPoint(const Eigen::Vector3d& p_sonar);

/// What the sonar's elevation beam does beyond its -3 dB aperture. MainLobe: a real array's
/// beam, whose main lobe and side lobes still image structure there (beam-aware carving
/// weighs it); Clipped: nothing is imaged outside +-aperture/2 (the seed paper's simulator and
/// ours with `--beam clipped`), so carving stays inside the aperture.
enum class ElevationBeam { MainLobe, Clipped };
/// Its name in mission.yaml's beam_pattern: "sinc" (MainLobe) or "clipped".
const char* elevationBeamName(ElevationBeam beam);

class SonarModel {
 public:
  /// Throws Error if the geometry is invalid (no bins, non-positive resolution, ...).
  SonarModel(std::string id, RangeBins range, BearingTable bearings, double vertical_aperture_rad);

  const std::string& id() const { return id_; }
  const RangeBins& range() const { return range_; }
  const BearingTable& bearings() const { return bearings_; }
  const BeamPattern& beamPattern() const { return beam_pattern_; }
  double verticalAperture() const { return beam_pattern_.aperture(); }
  /// The same sonar with another vertical aperture (radians).
  SonarModel withVerticalAperture(double vertical_aperture_rad) const {
    SonarModel other = *this;
    other.beam_pattern_ = BeamPattern(vertical_aperture_rad);
    return other;
  }
  ElevationBeam elevationBeam() const { return elevation_beam_; }
  /// The same sonar with another elevation beam.
  SonarModel withElevationBeam(ElevationBeam beam) const {
    SonarModel other = *this;
    other.elevation_beam_ = beam;
    return other;
  }
  /// How far off the axis the elevation beam is known to carry energy (radians): carving trusts
  /// a dark pixel out to the smaller of this and the declared beam's first null. 0 (the
  /// default): the first null. Set by the beam check where the frames show the tails end
  /// short of it (pipeline/beam_check.h).
  double elevationReach() const { return elevation_reach_rad_; }
  /// How far off the axis beam-aware carving trusts a dark pixel, radians: the reach, within
  /// [aperture/2, the declared sinc^2 beam's first null]; the first null where no reach is set.
  double mainLobeReach() const;
  SonarModel withElevationReach(double reach_rad) const {
    SonarModel other = *this;
    other.elevation_reach_rad_ = reach_rad;
    return other;
  }
  /// Full width of each beam across bearing between its -3 dB points (radians), when the
  /// sonar declares it; 0: not given, each beam taken as wide as its spacing. Real beams
  /// are often wider than their spacing (an Oculus M750d: 1 degree, 0.25 apart), which blurs
  /// the image across bearing (sonar/bearing_deblur.h undoes it).
  double horizontalBeamWidth() const { return horizontal_beam_width_rad_; }
  /// The same sonar with a horizontal beam width (>= 0, finite; throws Error otherwise).
  SonarModel withHorizontalBeamWidth(double width_rad) const;
  /// How the sonar's counts relate to the echo's power (frames are loaded as power).
  const IntensityScale& intensityScale() const { return intensity_scale_; }
  SonarModel withIntensityScale(IntensityScale scale) const {
    SonarModel other = *this;
    other.intensity_scale_ = scale;
    return other;
  }

  int rows() const { return range_.count; }
  int cols() const { return bearings_.count(); }

  /// Range and bearing at the centre of `pixel`, at elevation 0.
  Polar pixelCentre(const Pixel& pixel) const;
  /// The pixel that images a point, or nothing if the point lies outside the range window,
  /// the field of view or the vertical aperture (|elevation| > aperture / 2).
  std::optional<Pixel> pixelOf(const Eigen::Vector3d& p_sonar) const;
  /// The pixel of polar coordinates, same rules as pixelOf.
  std::optional<Pixel> pixelOf(const Polar& polar) const;

 private:
  std::string id_;
  RangeBins range_;
  BearingTable bearings_;
  BeamPattern beam_pattern_;
  ElevationBeam elevation_beam_ = ElevationBeam::MainLobe;
  double elevation_reach_rad_ = 0.0;
  double horizontal_beam_width_rad_ = 0.0;
  IntensityScale intensity_scale_;
};

}  // namespace sonarcarve
