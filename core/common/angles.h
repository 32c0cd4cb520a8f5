// Degree <-> radian conversion. SI units (radians) everywhere inside the engine;
// degrees only at the file and UI boundary.
#pragma once

#include <numbers>

namespace sonarcarve {

constexpr double degToRad(double deg) {
  return deg * std::numbers::pi / 180.0;
}
constexpr double radToDeg(double rad) {
  return rad * 180.0 / std::numbers::pi;
}

}  // namespace sonarcarve
