#include "sim/elevation_pattern.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "common/angles.h"
#include "common/error.h"
#include "common/input_limits.h"
#include "io/files/csv_table.h"
#include "io/files/input_file.h"
#include "sonar/beam_pattern.h"

namespace sonarcarve {
namespace {

constexpr char kTablePrefix[] = "table:";

double fromDecibels(double db) {
  return std::pow(10.0, db / 10.0);
}

// The pattern inside +-half, 0 beyond.
std::function<double(double)> within(double half, std::function<double(double)> power) {
  return [half, power = std::move(power)](double theta) {
    return std::abs(theta) <= half ? power(theta) : 0.0;
  };
}

// Power of a table at `theta`: linear in dB between rows, 0 outside them.
double tablePower(const std::vector<ElevationTableRow>& rows, double theta) {
  const double deg = radToDeg(theta);
  if (!(deg >= rows.front().elevation_deg && deg <= rows.back().elevation_deg)) {
    return 0.0;
  }
  const auto above = std::upper_bound(
      rows.begin(), rows.end(), deg,
      [](double d, const ElevationTableRow& row) { return d < row.elevation_deg; });
  if (above == rows.end()) {
    return fromDecibels(rows.back().gain_db);
  }
  const ElevationTableRow& a = *(above - 1);
  const ElevationTableRow& b = *above;
  const double t = (deg - a.elevation_deg) / (b.elevation_deg - a.elevation_deg);
  return fromDecibels(a.gain_db + t * (b.gain_db - a.gain_db));
}

// Cell `column` of a table's row as a finite number; an Error naming its line otherwise.
double number(const CsvTable& csv, const CsvTable::Row& row, std::size_t column) {
  const std::string& cell = row.cells[column];
  double value = 0.0;
  const auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), value);
  if (cell.empty() || ec != std::errc() || end != cell.data() + cell.size() ||
      !std::isfinite(value)) {
    throw Error(csv.file(), linePlace(row.line),
                std::string("expected ") + (column == 0 ? "elevation_deg" : "gain_db") +
                    " as a finite number, found '" + cell + "'");
  }
  return value;
}

}  // namespace

std::string elevationFamilyName(ElevationFamily family) {
  switch (family) {
    case ElevationFamily::Sinc2:
      return "sinc2";
    case ElevationFamily::Gaussian:
      return "gaussian";
    case ElevationFamily::Truncated:
      return "truncated";
    case ElevationFamily::Table:
      return "table";
  }
  return "sinc2";
}

ElevationBeamSpec elevationBeamSpec(const std::string& text) {
  ElevationBeamSpec spec;
  if (text == "sinc2") {
    spec.family = ElevationFamily::Sinc2;
  } else if (text == "gaussian") {
    spec.family = ElevationFamily::Gaussian;
  } else if (text == "truncated") {
    spec.family = ElevationFamily::Truncated;
  } else if (text.starts_with(kTablePrefix) && text.size() > sizeof(kTablePrefix) - 1) {
    spec.family = ElevationFamily::Table;
    const std::string file = text.substr(sizeof(kTablePrefix) - 1);
    spec.table =
        std::make_shared<const ElevationTable>(ElevationTable{file, readElevationTable(file)});
  } else {
    throw Error("simulator", "elevation beam",
                "expected sinc2, gaussian, truncated or table:FILE, not '" + text + "'");
  }
  return spec;
}

std::vector<ElevationTableRow> readElevationTable(const std::filesystem::path& path) {
  return parseElevationTable(readInputFile(path, "an elevation beam table", kMaxBeamTableFileBytes),
                             path.string());
}

std::vector<ElevationTableRow> parseElevationTable(std::string_view text, const std::string& file) {
  CsvOptions options;
  options.header = false;
  const CsvTable csv = CsvTable::parse(text, file, options);
  if (csv.header().size() != 2) {
    throw Error(file, csv.headerPlace(),
                "expected 2 values a line, elevation_deg,gain_db; found " +
                    std::to_string(csv.header().size()));
  }
  std::vector<ElevationTableRow> rows;
  for (const CsvTable::Row& row : csv.rows()) {
    if (rows.empty() && row.cells[0] == "elevation_deg" && row.cells[1] == "gain_db") {
      continue;  // the header line
    }
    const ElevationTableRow r{number(csv, row, 0), number(csv, row, 1)};
    if (!(std::abs(r.elevation_deg) < 90.0)) {
      throw Error(file, linePlace(row.line),
                  "expected an elevation between -90 and 90 degrees, found " + csv.text(row, 0));
    }
    if (!rows.empty() && !(r.elevation_deg > rows.back().elevation_deg)) {
      throw Error(file, linePlace(row.line),
                  "expected elevations sorted, strictly increasing: " + csv.text(row, 0) +
                      " after " + std::to_string(rows.back().elevation_deg));
    }
    rows.push_back(r);
  }
  if (rows.size() < 2) {
    throw Error(
        file, "",
        "expected at least 2 rows of elevation_deg,gain_db; found " + std::to_string(rows.size()));
  }
  return rows;
}

ElevationPattern::ElevationPattern(const ElevationBeamSpec& spec, double aperture_rad,
                                   int side_lobes)
    : family_(spec.family), aperture_rad_(aperture_rad) {
  const SincSquaredBeam sinc2(aperture_rad);  // checks the aperture
  switch (family_) {
    case ElevationFamily::Sinc2:
      traced_rad_ = sinc2.null(side_lobes + 1);
      power_ = within(traced_rad_, [sinc2](double t) { return sinc2.power(t); });
      break;
    case ElevationFamily::Gaussian: {
      traced_rad_ = std::sqrt(10.0) * 0.5 * aperture_rad;  // -3 dB x 10 = -30 dB
      const double half = 0.5 * aperture_rad;
      power_ = within(traced_rad_,
                      [half](double t) { return fromDecibels(-3.0 * (t / half) * (t / half)); });
      break;
    }
    case ElevationFamily::Truncated:
      traced_rad_ = sinc2.halfAngleAt(-6.0);
      power_ = within(traced_rad_, [sinc2](double t) { return sinc2.power(t); });
      break;
    case ElevationFamily::Table: {
      if (!spec.table || spec.table->rows.size() < 2) {
        throw Error("simulator", "elevation beam", "expected a table of at least 2 rows");
      }
      const auto table = spec.table;
      traced_rad_ = degToRad(std::max(std::abs(table->rows.front().elevation_deg),
                                      std::abs(table->rows.back().elevation_deg)));
      power_ = [table](double t) { return tablePower(table->rows, t); };
      break;
    }
  }
}

std::pair<double, double> ElevationPattern::interval(double level_db) const {
  if (!(level_db < 0.0)) {
    throw Error("beam pattern", "level", "expected a level below 0 dB");
  }
  const SincSquaredBeam sinc2(aperture_rad_);
  switch (family_) {
    case ElevationFamily::Sinc2: {
      const double h = sinc2.halfAngleAt(level_db);
      return {-h, h};
    }
    case ElevationFamily::Gaussian: {
      const double h = std::min(traced_rad_, 0.5 * aperture_rad_ * std::sqrt(level_db / -3.0));
      return {-h, h};
    }
    case ElevationFamily::Truncated: {
      const double h = std::min(traced_rad_, sinc2.halfAngleAt(level_db));
      return {-h, h};
    }
    case ElevationFamily::Table:
      break;
  }
  // A table: walked out from the axis in steps of a thousandth of a degree.
  const double threshold = fromDecibels(level_db);
  if (power(0.0) < threshold) {
    return {1.0, -1.0};  // empty
  }
  const double step = degToRad(1e-3);
  double lo = 0.0;
  double hi = 0.0;
  while (hi + step <= traced_rad_ && power(hi + step) >= threshold) {
    hi += step;
  }
  while (lo - step >= -traced_rad_ && power(lo - step) >= threshold) {
    lo -= step;
  }
  return {lo, hi};
}

}  // namespace sonarcarve
