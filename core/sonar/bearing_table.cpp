#include "sonar/bearing_table.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/angles.h"
#include "common/error.h"
#include "common/input_limits.h"
#include "common/quantile.h"

namespace sonarcarve {
namespace {

void requireBeamCount(std::size_t beams) {
  if (beams > static_cast<std::size_t>(kMaxBeams)) {
    throw Error("sonar model", "bearings",
                std::to_string(beams) + " beams: expected at most " + std::to_string(kMaxBeams));
  }
}

}  // namespace

BearingTable BearingTable::uniform(double fov_rad, int beams) {
  if (beams < 1 || !(fov_rad > 0.0) || !std::isfinite(fov_rad)) {
    throw Error("sonar model", "bearings",
                "expected a positive field of view and at least one beam");
  }
  requireBeamCount(static_cast<std::size_t>(beams));
  std::vector<double> centres(static_cast<std::size_t>(beams));
  const double step = fov_rad / beams;
  for (int j = 0; j < beams; ++j) {
    centres[static_cast<std::size_t>(j)] = -0.5 * fov_rad + (j + 0.5) * step;
  }
  BearingTable table(std::move(centres), true);
  // Exact edges and field of view, free of the rounding of midpoints between centres.
  for (int j = 0; j <= beams; ++j) {
    table.edges_[static_cast<std::size_t>(j)] = -0.5 * fov_rad + j * step;
  }
  table.fov_rad_ = fov_rad;
  return table;
}

BearingTable BearingTable::fromCentres(std::vector<double> centres_rad) {
  if (centres_rad.empty()) {
    throw Error("sonar model", "bearings", "expected at least one beam");
  }
  requireBeamCount(centres_rad.size());
  for (std::size_t j = 0; j < centres_rad.size(); ++j) {
    if (!std::isfinite(centres_rad[j])) {
      throw Error("sonar model", "beam " + std::to_string(j), "bearing is not a finite number");
    }
    if (j > 0 && !(centres_rad[j] > centres_rad[j - 1])) {
      throw Error("sonar model", "beam " + std::to_string(j),
                  "bearings must strictly increase from port to starboard");
    }
  }
  return BearingTable(std::move(centres_rad), false);
}

BearingTable::BearingTable(std::vector<double> centres_rad, bool uniform)
    : centres_(std::move(centres_rad)), uniform_(uniform) {
  const std::size_t n = centres_.size();
  edges_.resize(n + 1);
  for (std::size_t j = 1; j < n; ++j) {
    edges_[j] = 0.5 * (centres_[j - 1] + centres_[j]);
  }
  if (n == 1) {
    // A single beam has no neighbour to set its width; give it a nominal 1 degree.
    const double half_width = degToRad(0.5);
    edges_[0] = centres_[0] - half_width;
    edges_[1] = centres_[0] + half_width;
  } else {
    edges_[0] = centres_[0] - 0.5 * (centres_[1] - centres_[0]);
    edges_[n] = centres_[n - 1] + 0.5 * (centres_[n - 1] - centres_[n - 2]);
  }
  fov_rad_ = edges_[n] - edges_[0];
  std::vector<double> gaps;
  for (std::size_t j = 1; j < n; ++j) {
    gaps.push_back(centres_[j] - centres_[j - 1]);
  }
  median_spacing_ = gaps.empty() ? 0.0 : quantile(gaps, 0.5);
}

std::optional<int> BearingTable::beamOf(double bearing_rad) const {
  if (!(bearing_rad >= edges_.front()) || bearing_rad >= edges_.back()) {
    return std::nullopt;
  }
  if (uniform_) {
    const double step = (edges_.back() - edges_.front()) / count();
    const int beam = static_cast<int>((bearing_rad - edges_.front()) / step);
    return std::min(beam, count() - 1);
  }
  // First edge greater than the bearing; the beam is the interval before it.
  const auto it = std::upper_bound(edges_.begin(), edges_.end(), bearing_rad);
  return static_cast<int>(it - edges_.begin()) - 1;
}

}  // namespace sonarcarve
