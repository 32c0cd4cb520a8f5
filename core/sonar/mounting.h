// Mounting: where the sonar sits on the vehicle, as a translation (vehicle frame, metres) and
// a roll/pitch/yaw of the sonar frame relative to the vehicle frame.
#pragma once

#include <Eigen/Geometry>

#include "sonar/attitude.h"

namespace sonarcarve {

/// A sonar sits on its vehicle: an offset beyond this (metres) is an error in the mounting,
/// not a place (the longest survey ships are a few hundred metres).
inline constexpr double kMaxMountingOffset_m = 1000.0;

struct Mounting {
  Eigen::Vector3d translation_m = Eigen::Vector3d::Zero();
  RollPitchYaw rpy;

  Eigen::Isometry3d T_vehicle_sonar() const { return makeTransform(translation_m, rpy); }
};

}  // namespace sonarcarve
