#include "io/rosbag/bag_geofix.h"

#include <algorithm>
#include <cmath>

#include "common/error.h"
#include "geo/crs.h"
#include "geo/grid_projection.h"

namespace sonarcarve {
namespace {

// NavSatFix or GeoPoint: finite, latitude within 90 degrees, longitude within 180.
template <typename Message>
bool onTheEarth(const Message& f) {
  return std::isfinite(f.latitude_deg) && std::isfinite(f.longitude_deg) &&
         std::isfinite(f.altitude_m) && std::abs(f.latitude_deg) <= 90.0 &&
         std::abs(f.longitude_deg) <= 180.0;
}

}  // namespace

BagGeoOrigin bagGeoOrigin(const GeoPointMsg& point, const std::string& grid_crs,
                          const std::string& source, const std::string& place) {
  if (!onTheEarth(point)) {
    throw Error(source, place,
                "latitude " + std::to_string(point.latitude_deg) + ", longitude " +
                    std::to_string(point.longitude_deg) + ", altitude " +
                    std::to_string(point.altitude_m) +
                    ": expected finite WGS84 degrees within -90..90 and -180..180 and metres");
  }
  BagGeoOrigin origin;
  origin.crs = grid_crs.empty() ? utmZoneCrs(point.latitude_deg, point.longitude_deg) : grid_crs;
  const GridProjection grid(kWgs84Crs, origin.crs, source, place);
  const GridProjection::GridPoint p =
      grid.place(point.longitude_deg, point.latitude_deg, source, place);
  origin.ned_m = {p.north_m, p.east_m, -point.altitude_m};
  origin.true_north_bearing_rad = p.true_north_bearing_rad;
  return origin;
}

NavTrack trackTurnedToGrid(const NavTrack& track, double true_north_bearing_rad) {
  const Eigen::Quaterniond turn(
      Eigen::AngleAxisd(true_north_bearing_rad, Eigen::Vector3d::UnitZ()));
  std::vector<NavSample> samples = track.samples();
  for (NavSample& s : samples) {
    s.position_m = turn * s.position_m;
    s.q_world_vehicle = turn * s.q_world_vehicle;
  }
  return NavTrack(std::move(samples));
}

std::string leftOutFixes(const BagGeoNavigation& nav) {
  std::string text;
  const auto add = [&](std::size_t n, const char* why) {
    if (n > 0) {
      text += (text.empty() ? "" : ", ") + std::to_string(n) + " " + why;
    }
  };
  add(nav.no_fix, "with status STATUS_NO_FIX");
  add(nav.not_finite, "with a latitude, longitude or altitude not finite or off the Earth");
  add(nav.duplicates, "whose time did not increase");
  add(nav.outside_attitude, "outside the pose topic's times (no attitude there)");
  return text;
}

BagGeoNavigation bagGeoNavigation(std::vector<TimedFix> fixes,
                                  const std::optional<NavTrack>& attitude,
                                  const std::string& grid_crs, const std::string& source,
                                  const std::string& topic) {
  std::stable_sort(fixes.begin(), fixes.end(),
                   [](const TimedFix& a, const TimedFix& b) { return a.time_s < b.time_s; });
  BagGeoNavigation out{NavTrack({NavSample{}}), grid_crs, Eigen::Vector3d::Zero()};
  std::vector<NavSample> samples;
  std::vector<Eigen::Vector2d> xy;
  std::vector<std::string> places;
  for (const TimedFix& f : fixes) {
    if (f.fix.status <= kNavSatStatusNoFix) {
      ++out.no_fix;
    } else if (!onTheEarth(f.fix)) {
      ++out.not_finite;
    } else if (!samples.empty() && f.time_s <= samples.back().time_s) {
      ++out.duplicates;
    } else if (attitude && !attitude->covers(f.time_s)) {
      ++out.outside_attitude;
    } else {
      NavSample s;
      s.time_s = f.time_s;
      s.position_m = {0.0, 0.0, -f.fix.altitude_m};
      if (attitude) {
        s.q_world_vehicle = Eigen::Quaterniond(attitude->T_world_vehicle(f.time_s).linear());
      }
      samples.push_back(s);
      xy.emplace_back(f.fix.longitude_deg, f.fix.latitude_deg);
      places.push_back(f.place);
    }
  }
  if (samples.empty()) {
    const std::string why = leftOutFixes(out);
    throw Error(source, "topic " + topic,
                "no usable sensor_msgs/NavSatFix of " + std::to_string(fixes.size()) +
                    (why.empty() ? "" : " (" + why + ")") +
                    ": expected fixes with finite latitude, longitude and altitude");
  }
  if (out.crs.empty()) {
    out.crs = utmZoneCrs(xy.front().y(), xy.front().x());
  }
  const GridProjection grid(kWgs84Crs, out.crs, source, "topic " + topic);
  placeOnGrid(samples, xy, grid,
              {source, [&](std::size_t i) { return "topic " + topic + ", " + places[i]; }});
  out.first_fix_ned_m = {samples.front().position_m.x(), samples.front().position_m.y(), 0.0};
  out.track = NavTrack(std::move(samples));
  return out;
}

}  // namespace sonarcarve
