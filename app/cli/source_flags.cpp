#include "cli/source_flags.h"

#include "common/error.h"
#include "sonar/sonar_ranges.h"

namespace sonarcarve::cli {
namespace {

// "KEY=VALUE" -> key, value; throws a user error otherwise.
std::pair<std::string, std::string> keyValue(const std::string& text, const std::string& flag) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw Error(flag, "", "expected KEY=VALUE, found '" + text + "'");
  }
  return {text.substr(0, eq), text.substr(eq + 1)};
}

}  // namespace

void addSourceFlags(CLI::App& cmd, SourceFlags& flags) {
  cmd.add_option("--nav", flags.nav,
                 "Navigation CSV (default columns: time_s,north_m,east_m,down_m,roll_deg,"
                 "pitch_deg,yaw_deg); replaces a mission's own; a vendor log without it is "
                 "stationary at the origin");
  cmd.add_option("--nav-map", flags.nav_map, "Column mapping YAML for --nav (docs/formats.md)");
  cmd.add_option("--nav-column", flags.nav_columns,
                 "ROLE=COLUMN for --nav, repeatable: roles time, north, east, down|depth, "
                 "up|altitude, roll, pitch, yaw|heading; COLUMN is a header name or a 0-based "
                 "index")
      ->allow_extra_args(false);
  cmd.add_option("--nav-set", flags.nav_settings,
                 "KEY=VALUE for --nav, repeatable: units.time=s|ms|us, units.position=m|ft, "
                 "units.angles=deg|rad, conventions.heading=compass|enu, "
                 "conventions.pitch=bow_up|bow_down, conventions.roll=starboard_down|port_down, "
                 "delimiter=,|;|tab, header=true|false")
      ->allow_extra_args(false);
  cmd.add_option("--mounting", flags.mounting,
                 "Mounting YAML: translation_m and roll_pitch_yaw_deg of the sonar on the "
                 "vehicle");
  cmd.add_option("--time-offset", flags.time_offset_s,
                 "Seconds added to the frame times to put them on the navigation clock")
      ->capture_default_str();
  cmd.add_option("--aperture-deg", flags.aperture_deg,
                 "Vertical aperture (Oculus default: 20 below 1.5 MHz, 12 above)")
      ->check(CLI::Validator(
          [](const std::string& text) {
            double value = 0.0;
            return CLI::detail::lexical_cast(text, value)
                       ? outsideRange(value, kVerticalAperture).value_or("")
                       : "expected a number of degrees, got " + text;
          },
          "DEGREES"));
  cmd.add_option("--beam-pattern", flags.beam_pattern,
                 "Elevation beam of a recording that does not say: sinc (a real array's main "
                 "lobe, the default) or clipped (nothing outside +-aperture/2, as our simulator's "
                 "--beam clipped)")
      ->check(CLI::IsMember({"sinc", "clipped"}));
  cmd.add_option(
      "--sonar-topic", flags.sonar_topic,
      "ROS 2 bag: the sonar topic (default: the only sonar image or raw Oculus ping one)");
  cmd.add_option("--nav-topic", flags.nav_topic,
                 "ROS 2 bag: the navigation topic (default: the only Odometry, PoseStamped or "
                 "PoseWithCovarianceStamped one); with a position fix topic, the attitude's");
  cmd.add_option("--fix-topic", flags.fix_topic,
                 "ROS 2 bag: the sensor_msgs/NavSatFix topic whose WGS84 fixes are the "
                 "vehicle's positions (default: the only one, if any)");
  cmd.add_option("--origin-topic", flags.origin_topic,
                 "ROS 2 bag: the geographic_msgs/GeoPoint or GeoPointStamped topic whose first "
                 "WGS84 point is the mission origin, as mission.yaml's origin (default: the "
                 "only one, if any)");
  cmd.add_option("--sonar-axes", flags.sonar_axes,
                 "ROS 2 bag: frame of the beam directions: z-forward (the message comment: Z "
                 "forward, X up), x-forward (X forward, Y left, as some simulators), frd (X "
                 "forward, Y starboard, Z down), auto")
      ->check(CLI::IsMember({"auto", "z-forward", "x-forward", "frd"}))
      ->capture_default_str();
  cmd.add_option("--image-layout", flags.image_layout,
                 "ROS 2 bag: order of the image data: range-major (data[range * beams + beam]) "
                 "or beam-major (data[beam * ranges + range])")
      ->check(CLI::IsMember({"range-major", "beam-major"}))
      ->capture_default_str();
  cmd.add_option("--time-source", flags.time_source,
                 "ROS 2 bag: frame and pose times from the header stamps or the bag's receive "
                 "times")
      ->check(CLI::IsMember({"header", "receive"}))
      ->capture_default_str();
}

OpenOptions openOptionsFrom(const SourceFlags& flags) {
  OpenOptions options;
  options.nav_csv = flags.nav;
  options.mounting = flags.mounting;
  options.time_offset_s = flags.time_offset_s;
  if (flags.aperture_deg > 0.0) {
    options.vertical_aperture_deg = flags.aperture_deg;
  }
  if (!flags.beam_pattern.empty()) {
    options.elevation_beam =
        flags.beam_pattern == "clipped" ? ElevationBeam::Clipped : ElevationBeam::MainLobe;
  }
  options.bag.sonar_topic = flags.sonar_topic;
  options.bag.nav_topic = flags.nav_topic;
  options.bag.fix_topic = flags.fix_topic;
  options.bag.origin_topic = flags.origin_topic;
  options.bag.axes = enumFromString<SonarAxes>(flags.sonar_axes).value_or(SonarAxes::Auto);
  options.bag.layout =
      enumFromString<ImageLayout>(flags.image_layout).value_or(ImageLayout::RangeMajor);
  options.bag.time = enumFromString<BagTime>(flags.time_source).value_or(BagTime::Header);
  if (!flags.nav_map.empty()) {
    options.nav_mapping = readNavMapping(flags.nav_map);
  }
  for (const std::string& c : flags.nav_columns) {
    const auto [role, column] = keyValue(c, "--nav-column");
    setNavMapping(options.nav_mapping, "columns." + role, column, "--nav-column");
  }
  for (const std::string& s : flags.nav_settings) {
    const auto [key, value] = keyValue(s, "--nav-set");
    setNavMapping(options.nav_mapping, key, value, "--nav-set");
  }
  if (flags.nav.empty() &&
      (!flags.nav_map.empty() || !flags.nav_columns.empty() || !flags.nav_settings.empty())) {
    throw Error("--nav-map", "", "a navigation mapping needs --nav NAV.csv");
  }
  return options;
}

}  // namespace sonarcarve::cli
