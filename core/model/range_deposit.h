// Range binning of returns, shared by the simulator and the forward model: a return at one
// range goes whole into the bin that contains it (RangeBins::binOf); a return spread between two
// ranges is shared among the bins in proportion to the length of each bin it covers.
#pragma once

#include "sonar/range_bins.h"

namespace sonarcarve {

/// Adds `energy` into the bin of `range_m`, if the range lies in the window.
template <typename Real>
void depositAtRange(double range_m, Real energy, const RangeBins& bins, Real* column) {
  if (const auto bin = bins.binOf(range_m)) {
    column[*bin] += energy;
  }
}

/// Adds `energy` spread uniformly over the ranges [r0, r1] (either order) into the column.
void spreadOverRange(float r0, float r1, float energy, const RangeBins& bins, float* column);

}  // namespace sonarcarve
