// Physically meaningful ranges of a sonar's declared geometry and mounting: far wider than any
// imaging sonar, narrow enough that a value outside is an error in the file, not a sensor (a
// range resolution of 1e-300 m, an aperture of 1e-300 degrees). Readers check each key
// against its range and name the file, the key and the range (docs/reliability.md).
#pragma once

#include <optional>
#include <string>

namespace sonarcarve {

struct PhysicalRange {
  double min = 0.0;
  double max = 0.0;
  const char* unit = "";
  bool max_open = false;  ///< the maximum itself is outside
};

/// Nearest range of the first bin: sonars start imaging within a few metres.
inline constexpr PhysicalRange kNearRange{0.0, 1000.0, "m"};
/// Length of a range bin: imaging sonars have 3 mm to 10 cm.
inline constexpr PhysicalRange kRangeResolution{1e-4, 10.0, "m"};
/// Farthest range (nearest + bins x resolution): imaging sonars reach a few hundred metres.
inline constexpr double kMaxFarRange_m = 10000.0;
/// Horizontal field of view of the fan: imaging sonars have 12 to 130 degrees.
inline constexpr PhysicalRange kFieldOfView{0.1, 360.0, "degrees", true};
/// A beam's bearing in an explicit table.
inline constexpr PhysicalRange kBearing{-180.0, 180.0, "degrees", true};
/// Vertical aperture (elevation beam width): imaging sonars have 1 to 30 degrees.
inline constexpr PhysicalRange kVerticalAperture{0.1, 180.0, "degrees", true};
/// A beam's -3 dB width across bearing (and under the field of view).
inline constexpr PhysicalRange kHorizontalBeamWidth{0.01, 360.0, "degrees", true};
/// Mounting angles: a turn either way.
inline constexpr PhysicalRange kMountingAngle{-360.0, 360.0, "degrees"};
/// Speed of sound in water: 1400 to 1560 m/s in the sea, wider for fresh water and error.
inline constexpr PhysicalRange kSoundSpeed{1000.0, 2000.0, "m/s"};
/// Intensity scales: the decibels of full scale, the count of full scale, a gamma exponent.
inline constexpr PhysicalRange kFullScaleDb{1.0, 200.0, "dB"};
inline constexpr PhysicalRange kFullScaleCount{1.0, 4294967295.0, "counts"};
inline constexpr PhysicalRange kGammaExponent{0.01, 10.0, ""};

/// "expected 0.0001 to 10 m, got 1e-300" when `value` is outside `range` (or not finite);
/// nothing when it is within.
std::optional<std::string> outsideRange(double value, const PhysicalRange& range);

/// One quantity a recording (a vendor log, a bag) declares about its sonar, with the name of
/// the field it was read from, so that an error names the recording's own field.
struct RecordedQuantity {
  std::string field;  ///< "rangeResolution", "ranges", "tx_beamwidths"; empty: not recorded
  double value = 0.0;
};

/// A recording's sonar geometry: what the readers of Oculus logs, ARIS recordings and ROS 2
/// bags read from each frame's header or message.
struct RecordedGeometry {
  RecordedQuantity near_range_m;
  RecordedQuantity range_resolution_m;
  int bins = 0;
  RecordedQuantity field_of_view_deg;  ///< the span of the bearing table
  RecordedQuantity vertical_aperture_deg;
};

/// The first quantity of `g` outside the ranges above, as "rangeResolution: expected 1e-04 to
/// 10 m, got 1e-300" (the farthest range, nearest + bins x resolution, at most kMaxFarRange_m);
/// nothing when every one is within. The readers throw it with the file and the frame.
std::optional<std::string> recordedGeometryProblem(const RecordedGeometry& g);

}  // namespace sonarcarve
