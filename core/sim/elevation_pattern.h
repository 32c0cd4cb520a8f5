// ElevationPattern: the power pattern in elevation that the simulator's realistic beam weights
// its rays with (`simulate --elevation-beam`), chosen apart from the beam the mission declares,
// since real sonars never match their spec sheets. Every family is 1 (0 dB) on the axis and
// set by the sonar's -3 dB aperture A; the pattern is 0 beyond the elevation it is traced to.
//
// - sinc2: a uniform array's sinc^2 (sonar/beam_pattern.h), -3 dB at +-A/2, traced to the null
//   after the last traced side lobe (the second null, +-45.2 degrees for A = 20 degrees).
// - gaussian: 10^(-0.3 (2 theta / A)^2), -3 dB at +-A/2, traced to where it falls to -30 dB,
//   +-sqrt(10) A/2 (+-31.6 degrees): no side lobes.
// - truncated: sinc^2's main lobe cut to 0 past its -6 dB points (+-13.6 degrees): a beam as
//   wide as declared at -3 dB but without its tails.
// - table: a measured pattern, gain in dB against elevation in degrees (a CSV file),
//   interpolated linearly in dB between rows and 0 outside the table.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sonarcarve {

enum class ElevationFamily { Sinc2, Gaussian, Truncated, Table };

struct ElevationTableRow {
  double elevation_deg = 0.0;  ///< positive up
  double gain_db = 0.0;        ///< power relative to the axis of the declared beam
};

/// A measured pattern and the file it was read from.
struct ElevationTable {
  std::string file;                     ///< the CSV file, as given
  std::vector<ElevationTableRow> rows;  ///< elevations strictly increasing
};

/// A family and, for a table, the table (shared: settings holding it are copied freely).
struct ElevationBeamSpec {
  ElevationFamily family = ElevationFamily::Sinc2;
  std::shared_ptr<const ElevationTable> table;  ///< table only
};

/// "sinc2" | "gaussian" | "truncated" | "table:FILE" (the file read and checked); throws Error
/// on anything else.
ElevationBeamSpec elevationBeamSpec(const std::string& text);
/// The family's name: "sinc2", "gaussian", "truncated" or "table".
std::string elevationFamilyName(ElevationFamily family);

/// An elevation table: lines of `elevation_deg,gain_db` (an optional header line naming those
/// columns, '#' comments and blank lines skipped), at least 2 rows, elevations strictly
/// increasing within (-90, 90) degrees, every value finite. Throws Error naming the file, the
/// line and what was expected.
std::vector<ElevationTableRow> readElevationTable(const std::filesystem::path& path);
/// The same from text in memory; `file` names it in messages.
std::vector<ElevationTableRow> parseElevationTable(std::string_view text, const std::string& file);

class ElevationPattern {
 public:
  /// `aperture_rad`: the -3 dB aperture (> 0); `side_lobes`: sinc2's traced side lobes (>= 0).
  ElevationPattern(const ElevationBeamSpec& spec, double aperture_rad, int side_lobes);

  ElevationFamily family() const { return family_; }
  /// Power in [0, 1] (a table may exceed 1) of a return at `elevation_rad`; 0 beyond the traced
  /// extent.
  double power(double elevation_rad) const { return power_(elevation_rad); }
  /// The elevation traced on each side of the axis: the pattern is 0 beyond.
  double tracedHalfAngle() const { return traced_rad_; }
  /// The interval of elevations around the axis over which the power stays at or above
  /// `level_db` (< 0): sinc2's main lobe only, not its side lobes.
  std::pair<double, double> interval(double level_db) const;

 private:
  ElevationFamily family_;
  double aperture_rad_;
  double traced_rad_ = 0.0;
  std::function<double(double)> power_;
};

}  // namespace sonarcarve
