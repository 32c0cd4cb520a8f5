// NaN and infinite coordinates are refused where points enter: a NaN compares false with
// everything, so one would silently pass every distance test downstream.
#pragma once

#include <Eigen/Core>
#include <string>

namespace sonarcarve {

/// Throws Error(source, place, ...) unless the three coordinates are finite numbers.
void requireFinitePoint(const Eigen::Vector3f& p, const std::string& source,
                        const std::string& place);

}  // namespace sonarcarve
