// The vehicle's position from sensor_msgs/NavSatFix messages (docs/formats.md, "ROS 2 bags",
// "Geodetic navigation"): latitude and longitude (WGS84) placed on a projected grid by PROJ, as
// nav.csv's latitude_deg and longitude_deg are (docs/conventions.md, "Geodetic navigation and
// CRSs"), down = -altitude. The attitude comes from the bag's pose topic, paired in time: each
// fix takes the pose topic's attitude at the fix's time (slerp between the two poses around
// it), its heading from true north turned to grid north at the fix. Left out, and counted:
// fixes whose status is STATUS_NO_FIX, whose latitude, longitude or altitude is not finite or
// off the Earth, whose time does not increase, or (with a pose topic) whose time lies outside
// the poses' (no extrapolation).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "io/rosbag/ros_messages.h"
#include "sonar/nav_track.h"

namespace sonarcarve {

struct TimedFix {
  double time_s = 0.0;
  NavSatFixMsg fix;
  std::string place;  ///< the message, for errors
};

struct BagGeoNavigation {
  NavTrack track;   ///< world NED on the grid of `crs`
  std::string crs;  ///< the grid: the first fix's UTM zone
  Eigen::Vector3d first_fix_ned_m = Eigen::Vector3d::Zero();  ///< grid north, east, 0
  std::size_t no_fix = 0, not_finite = 0, duplicates = 0, outside_attitude = 0;
};

/// The track of the usable fixes, attitudes from `attitude` (world NED from true north; none:
/// level, heading north). `grid_crs` empty: the first usable fix's UTM zone. Throws Error
/// naming `source` and `topic` when no fix is usable, saying how many were left out and why.
BagGeoNavigation bagGeoNavigation(std::vector<TimedFix> fixes,
                                  const std::optional<NavTrack>& attitude,
                                  const std::string& grid_crs, const std::string& source,
                                  const std::string& topic);

/// The mission origin a geographic_msgs GeoPoint gives (docs/formats.md, "Geodetic
/// positions"): its WGS84 latitude and longitude on the grid of `grid_crs` (empty: the point's
/// own UTM zone), down = -altitude, and true north's bearing from grid north there.
struct BagGeoOrigin {
  Eigen::Vector3d ned_m = Eigen::Vector3d::Zero();
  std::string crs;
  double true_north_bearing_rad = 0.0;
};
/// Throws Error naming `source` and `place` for a point not finite or off the Earth.
BagGeoOrigin bagGeoOrigin(const GeoPointMsg& point, const std::string& grid_crs,
                          const std::string& source, const std::string& place);

/// A track local to an origin in a frame aligned with true north (as an odometry frame whose
/// datum is a GeoPoint) turned about the origin onto the grid: positions and attitudes
/// rotated by `true_north_bearing_rad` about down.
NavTrack trackTurnedToGrid(const NavTrack& track, double true_north_bearing_rad);

/// "12 no fix, 1 not finite": the fixes left out, for a warning; empty when none was.
std::string leftOutFixes(const BagGeoNavigation& nav);

}  // namespace sonarcarve
