#include "sonar/mission_origin.h"

#include <charconv>
#include <cmath>
#include <sstream>

#include "common/error.h"
#include "common/number_text.h"

namespace sonarcarve {

Eigen::Vector3d chooseMissionOrigin(const NavTrack& nav) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY);
  Eigen::Vector3d hi = Eigen::Vector3d::Constant(-INFINITY);
  for (const NavSample& s : nav.samples()) {
    lo = lo.cwiseMin(s.position_m);
    hi = hi.cwiseMax(s.position_m);
  }
  if (lo.cwiseAbs().maxCoeff() <= kNearZeroLimit_m &&
      hi.cwiseAbs().maxCoeff() <= kNearZeroLimit_m) {
    return Eigen::Vector3d::Zero();
  }
  Eigen::Vector3d origin;
  for (int a = 0; a < 3; ++a) {
    // The centre of the box, halved before adding so that no sum can overflow.
    const double centre = lo[a] / 2.0 + hi[a] / 2.0;
    origin[a] = std::round(centre / kOriginStep_m) * kOriginStep_m + 0.0;  // never -0
  }
  return origin;
}

NavTrack translatedTrack(const NavTrack& nav, const Eigen::Vector3d& offset_m) {
  if (offset_m.isZero()) {
    return nav;  // as read, to the bit (a -0 stays -0)
  }
  std::vector<NavSample> samples = nav.samples();
  for (NavSample& s : samples) {
    s.position_m += offset_m;
  }
  return NavTrack(std::move(samples));
}

void requirePlausiblePosition(const Eigen::Vector3d& position_m, const std::string& file,
                              const std::string& place) {
  if (position_m.allFinite() && position_m.cwiseAbs().maxCoeff() <= kMaxNavCoordinate_m) {
    return;
  }
  std::ostringstream found;
  found.precision(17);
  found << position_m.x() << ", " << position_m.y() << ", " << position_m.z();
  throw Error(file, place,
              "position (north, east, down) = (" + found.str() +
                  ") m: expected finite coordinates within 1e8 m of zero (world NED metres, "
                  "e.g. UTM northing and easting)");
}

std::optional<std::string> mountingOffsetProblem(const Eigen::Vector3d& translation_m) {
  if (translation_m.norm() <= kMaxMountingOffset_m) {
    return std::nullopt;
  }
  return "the sonar " + shortestNumber(translation_m.norm()) +
         " m from the vehicle's reference point: expected a mounting offset within " +
         shortestNumber(kMaxMountingOffset_m) + " m (metres, vehicle frame)";
}

std::string nedText(const Eigen::Vector3d& p_ned_m) {
  std::string text;
  for (int a = 0; a < 3; ++a) {
    char buffer[400];  // a double in fixed notation: up to 309 digits and 17 decimals
    const auto result =
        std::to_chars(buffer, buffer + sizeof(buffer), p_ned_m[a], std::chars_format::fixed);
    text += (a > 0 ? " " : "") + std::string(buffer, result.ptr);
  }
  return text;
}

std::string originComment(const Eigen::Vector3d& origin_ned_m) {
  return std::string(kOriginCommentKeyword) + " " + nedText(origin_ned_m) +
         " (local coordinates: world NED = local + origin)";
}

}  // namespace sonarcarve
