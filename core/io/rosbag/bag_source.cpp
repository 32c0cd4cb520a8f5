// ROS 2 bags (MCAP, SQLite3, or a bag folder) opened in place (docs/formats.md, "ROS 2
// bags"): the messages of the sonar topic (sonar images, or raw Oculus pings:
// io/rosbag/bag_oculus.h) are the frames, indexed and checked on open, decoded on demand; the
// navigation topic gives the track and /tf_static the sonar's mounting, unless --nav and --mounting
// replace them. Topics, conventions and the clock are chosen by OpenOptions::bag; what was chosen
// and assumed goes to Mission::contents for `info`.
#include <algorithm>
#include <functional>
#include <numeric>

#include "common/error.h"
#include "io/frame_source.h"
#include "io/rosbag/bag_geofix.h"
#include "io/rosbag/bag_navigation.h"
#include "io/rosbag/bag_oculus.h"
#include "io/rosbag/bag_sonar.h"
#include "io/rosbag/bag_summary.h"
#include "io/rosbag/ros_bag.h"
#include "sonar/mission_origin.h"

namespace sonarcarve {
namespace {

// The image of a sonar message's CDR bytes; `place` names the message in errors.
using BagImageDecoder =
    std::function<cv::Mat(std::span<const std::uint8_t> cdr, const std::string& place)>;

class BagSource final : public FrameSource {
 public:
  BagSource(std::shared_ptr<const RosBag> bag, std::string sonar_id, BagImageDecoder decode,
            std::vector<BagFrameRef> frames)
      : bag_(std::move(bag)),
        sonar_id_(std::move(sonar_id)),
        decode_(std::move(decode)),
        frames_(std::move(frames)) {}

  std::string kind() const override { return "ROS 2 bag, " + bag_->storage(); }
  std::size_t size() const override { return frames_.size(); }
  Frame load(std::size_t index) const override {
    const BagFrameRef& f = frames_.at(index);
    const BagMessage& m = bag_->messages()[f.message];
    Frame frame;
    frame.time_s = f.time_s;
    frame.sonar_id = sonar_id_;
    frame.image = decode_(bag_->payload(m), m.place);
    return frame;
  }

 private:
  std::shared_ptr<const RosBag> bag_;
  std::string sonar_id_;
  BagImageDecoder decode_;
  std::vector<BagFrameRef> frames_;
};

std::string kindName(RosMessageKind kind) {
  switch (kind) {
    case RosMessageKind::SonarImage:
      return "sonar";
    case RosMessageKind::VehiclePose:
      return "navigation (Odometry, PoseStamped or PoseWithCovarianceStamped)";
    case RosMessageKind::Transforms:
      return "transforms";
    case RosMessageKind::GeoFix:
      return "position fix (sensor_msgs/NavSatFix)";
    case RosMessageKind::GeoOrigin:
      return "origin (geographic_msgs/GeoPoint or GeoPointStamped)";
    case RosMessageKind::Other:
      break;
  }
  return "other";
}

// The types a topic asked for by a flag must have. (--fix-topic on an Odometry topic was told
// "expected nav_msgs/msg/Odometry, ...", the kind of --nav-topic.)
std::string expectedOf(RosMessageKind kind) {
  switch (kind) {
    case RosMessageKind::SonarImage:
      return std::string(kProjectedSonarImageType) +
             " (or acoustic_msgs/msg/SonarImage), or raw Oculus pings (a uint8[] field starting "
             "with the Oculus magic 53 4F)";
    case RosMessageKind::VehiclePose:
      return "nav_msgs/msg/Odometry, geometry_msgs/msg/PoseStamped or "
             "geometry_msgs/msg/PoseWithCovarianceStamped";
    case RosMessageKind::Transforms:
      return kTfMessageType;
    case RosMessageKind::GeoFix:
      return kNavSatFixType;
    case RosMessageKind::GeoOrigin:
      return "geographic_msgs/msg/GeoPoint or geographic_msgs/msg/GeoPointStamped";
    case RosMessageKind::Other:
      break;
  }
  return "a known message type";
}

// The topic to read: the one `requested`, or else the only topic of `kind`. Returns nothing
// when the bag has none and none was requested.
std::optional<std::size_t> chooseTopic(const RosBag& bag, const BagTopicKinds& kinds,
                                       RosMessageKind kind, const std::string& requested,
                                       const std::string& flag) {
  std::vector<std::size_t> candidates;
  std::string listed;
  for (std::size_t t = 0; t < bag.topics().size(); ++t) {
    const BagTopic& topic = bag.topics()[t];
    if (kinds.is(t, kind)) {
      candidates.push_back(t);
      listed += (listed.empty() ? "" : ", ") + topic.name + " (" + topic.type + ")";
    }
  }
  const std::string source = bag.path().string();
  if (!requested.empty()) {
    for (std::size_t t = 0; t < bag.topics().size(); ++t) {
      if (bag.topics()[t].name != requested) {
        continue;
      }
      if (!kinds.is(t, kind)) {
        throw Error(
            source, "topic " + requested,
            "type " + bag.topics()[t].type + " (" + flag + "): expected " + expectedOf(kind));
      }
      return t;
    }
    throw Error(source, "",
                "no topic " + requested + " (" + flag + "); " + kindName(kind) +
                    " topics: " + (listed.empty() ? "none" : listed));
  }
  if (candidates.size() > 1) {
    throw Error(source, "",
                std::to_string(candidates.size()) + " " + kindName(kind) + " topics: " + listed +
                    "; choose one with " + flag);
  }
  if (candidates.empty()) {
    return std::nullopt;
  }
  return candidates.front();
}

double timeOf(const BagMessage& m, const RosHeader& header, BagTime clock) {
  return (clock == BagTime::Header ? header.stamp_ns : m.receive_ns) * 1e-9;
}

// Every message of `topic`, decoded by `decode`; those that fail are reported and skipped.
template <typename Decode>
void forEachMessage(const RosBag& bag, std::size_t topic, std::vector<std::string>& problems,
                    Decode decode) {
  const std::string source = bag.path().string();
  for (std::size_t i = 0; i < bag.messages().size(); ++i) {
    const BagMessage& m = bag.messages()[i];
    if (m.topic != topic) {
      continue;
    }
    try {
      decode(i, m, bag.payload(m));
    } catch (const Error& e) {
      problems.push_back(std::string(e.what()) + " (message skipped)");
    }
  }
}

void requireCdr(const RosBag& bag, std::size_t topic) {
  const BagTopic& t = bag.topics()[topic];
  if (!t.encoding.empty() && t.encoding != "cdr") {
    throw Error(bag.path().string(), "topic " + t.name,
                "message encoding '" + t.encoding + "': expected cdr (ROS 2)");
  }
}

// A sonar topic's frames, however its messages carry them.
struct SonarFrames {
  std::optional<SonarModel> sonar;
  SonarAxes axes = SonarAxes::XForward;  ///< of the sonar frame, for the /tf_static mounting
  std::vector<BagFrameRef> frames;
  std::string frame_id;
  std::vector<std::string> notes;
  BagImageDecoder decode;
};

SonarFrames indexSonarImages(const std::shared_ptr<const RosBag>& bag, std::size_t topic,
                             const OpenOptions& options, std::vector<std::string>& problems) {
  SonarFrames out;
  std::optional<BagSonarGeometry> geometry;
  const std::string source = bag->path().string();
  const std::string type = bag->topics()[topic].type;
  // The older SonarImage states its frame and layout; the options are for ProjectedSonarImage.
  const bool legacy = isLegacySonarImage(type);
  const SonarAxes axes = legacy ? SonarAxes::Frd : options.bag.axes;
  const ImageLayout layout = legacy ? ImageLayout::BeamMajor : options.bag.layout;
  forEachMessage(*bag, topic, problems, [&](std::size_t i, const BagMessage& m, const auto& bytes) {
    const ProjectedSonarImageMsg msg = decodeSonarImage(type, bytes, source, m.place);
    if (!geometry) {
      geometry = bagSonarGeometry(msg, axes, layout, options.vertical_aperture_deg, "ros-bag",
                                  source, m.place);
      if (legacy) {
        geometry->notes.push_back(
            "acoustic_msgs/msg/SonarImage: azimuths in its NED sonar frame and azimuth-major "
            "data, as the message defines (--sonar-axes and --image-layout do not apply)");
      }
      bagSonarImage(msg, *geometry, source, m.place);
      out.frame_id = msg.header.frame_id;
    }
    checkBagSonarMessage(msg, *geometry, source, m.place);
    out.frames.push_back({timeOf(m, msg.header, options.bag.time) + options.time_offset_s, i});
  });
  if (!geometry) {
    throw Error(
        source, "topic " + bag->topics()[topic].name,
        "no readable sonar message" +
            (problems.empty() ? std::string() : " (first problem: " + problems.front() + ")"));
  }
  std::stable_sort(out.frames.begin(), out.frames.end(),
                   [](const BagFrameRef& a, const BagFrameRef& b) { return a.time_s < b.time_s; });
  out.sonar = geometry->sonar;
  out.axes = geometry->axes;
  out.notes = geometry->notes;
  out.decode = [type, source, g = std::move(*geometry)](std::span<const std::uint8_t> cdr,
                                                        const std::string& place) {
    return bagSonarImage(decodeSonarImage(type, cdr, source, place), g, source, place);
  };
  return out;
}

// Raw Oculus pings: their bearings are the sonar's own, in a REP-103 sensor frame (X forward).
SonarFrames indexOculusPings(const std::shared_ptr<const RosBag>& bag, std::size_t topic,
                             const OpenOptions& options, std::vector<std::string>& problems) {
  BagOculusFrames pings = indexOculusFrames(*bag, topic, options.bag.time, options.time_offset_s,
                                            options.vertical_aperture_deg, problems);
  SonarFrames out;
  out.sonar = pings.sonar;
  out.axes = SonarAxes::XForward;
  out.frames = std::move(pings.frames);
  out.frame_id = pings.frame_id;
  out.notes = std::move(pings.notes);
  const std::string source = bag->path().string();
  out.decode = [source, sonar = *pings.sonar, name = bag->topics()[topic].name](
                   std::span<const std::uint8_t> cdr, const std::string& place) {
    return bagOculusImage(cdr, sonar, source, "topic " + name + ", " + place);
  };
  return out;
}

std::vector<RosTransformMsg> staticTransforms(const RosBag& bag,
                                              std::vector<std::string>& problems) {
  std::vector<RosTransformMsg> all;
  const std::string source = bag.path().string();
  for (std::size_t t = 0; t < bag.topics().size(); ++t) {
    const BagTopic& topic = bag.topics()[t];
    if (rosMessageKind(topic.type) != RosMessageKind::Transforms ||
        (topic.name != "/tf_static" && topic.name != "tf_static")) {
      continue;
    }
    forEachMessage(bag, t, problems, [&](std::size_t, const BagMessage& m, const auto& bytes) {
      const auto transforms = decodeTfMessage(bytes, source, m.place);
      all.insert(all.end(), transforms.begin(), transforms.end());
    });
  }
  return all;
}

// The pose topic's track (Odometry, PoseStamped...), when the bag has one.
std::optional<BagNavigation> poseNavigation(const RosBag& bag, const BagTopicKinds& kinds,
                                            const OpenOptions& options,
                                            std::vector<std::string>& problems) {
  const auto nav_topic =
      chooseTopic(bag, kinds, RosMessageKind::VehiclePose, options.bag.nav_topic, "--nav-topic");
  if (!nav_topic) {
    return std::nullopt;
  }
  requireCdr(bag, *nav_topic);
  const std::string source = bag.path().string();
  std::vector<TimedPose> poses;
  const std::string type = bag.topics()[*nav_topic].type;
  forEachMessage(bag, *nav_topic, problems, [&](std::size_t, const BagMessage& m, const auto& b) {
    const RosPoseMsg pose = decodeRosPose(type, b, source, m.place);
    poses.push_back({timeOf(m, pose.header, options.bag.time), pose});
  });
  const std::string name = bag.topics()[*nav_topic].name;
  BagNavigation nav = bagNavigation(std::move(poses), source, name);
  nav.topic = name;
  nav.description = "navigation topic " + name + ": " + describe(nav.conventions) +
                    ", converted to world NED, vehicle FRD";
  if (nav.duplicates > 0) {
    problems.push_back(source + ": topic " + name + ": " + std::to_string(nav.duplicates) +
                       " poses whose time did not increase (left out)");
  }
  return nav;
}

// The vehicle's positions from the NavSatFix topic, its attitude from the pose topic's at each
// fix; the mission's grid is the first fix's UTM zone, its origin the first fix (depth 0).
void placeOnFixes(Mission& mission, const RosBag& bag, std::size_t topic,
                  const std::optional<BagNavigation>& poses, const OpenOptions& options,
                  std::vector<std::string>& problems, std::vector<std::string>& contents) {
  requireCdr(bag, topic);
  const std::string source = bag.path().string();
  const std::string name = bag.topics()[topic].name;
  std::vector<TimedFix> fixes;
  forEachMessage(bag, topic, problems, [&](std::size_t, const BagMessage& m, const auto& bytes) {
    const NavSatFixMsg fix = decodeNavSatFix(bytes, source, m.place);
    fixes.push_back({timeOf(m, fix.header, options.bag.time), fix, m.place});
  });
  const std::optional<NavTrack> attitude =
      poses ? std::optional<NavTrack>(poses->track) : std::nullopt;
  const BagGeoNavigation geo = bagGeoNavigation(std::move(fixes), attitude, "", source, name);
  mission.crs = geo.crs;
  mission.origin_ned_m = geo.first_fix_ned_m;
  mission.nav = translatedTrack(geo.track, -geo.first_fix_ned_m);
  mission.nav_file = bag.path().filename().string() + " topic " + name;
  contents.push_back("position topic " + name +
                     " (sensor_msgs/NavSatFix): WGS84 latitude and longitude on the grid of " +
                     geo.crs + ", down = -altitude, origin at the first fix; attitude " +
                     (poses ? "from " + poses->topic + " at each fix's time"
                            : std::string("level, heading north (no pose topic)")));
  if (!poses) {
    mission.warnings.push_back("no pose topic beside " + name +
                               ": the vehicle's attitude is taken level, heading north");
  }
  const std::string left_out = leftOutFixes(geo);
  if (!left_out.empty()) {
    problems.push_back(source + ": topic " + name + ": fixes left out: " + left_out);
  }
}

// The mission origin from the origin topic's first GeoPoint, as mission.yaml's origin: on the
// grid of the fixes when the bag has them (their track moved to it), else on the point's UTM
// zone, the pose topic's track taken as local to it in a frame aligned with true north (an
// odometry whose datum is the point) and turned to grid north.
void placeAtGeoOrigin(Mission& mission, const RosBag& bag, std::size_t topic, bool on_fixes,
                      std::vector<std::string>& problems, std::vector<std::string>& contents) {
  requireCdr(bag, topic);
  const std::string source = bag.path().string();
  const BagTopic& t = bag.topics()[topic];
  std::optional<GeoPointMsg> first;
  std::string place;
  std::size_t count = 0;
  forEachMessage(bag, topic, problems, [&](std::size_t, const BagMessage& m, const auto& bytes) {
    ++count;
    if (!first) {
      first = decodeGeoPoint(t.type, bytes, source, m.place);
      place = m.place;
    }
  });
  if (!first) {
    throw Error(source, "topic " + t.name,
                "no message: expected a " + expectedOf(RosMessageKind::GeoOrigin) +
                    " (the mission origin; --origin-topic)");
  }
  const BagGeoOrigin origin =
      bagGeoOrigin(*first, on_fixes ? mission.crs : "", source, "topic " + t.name + ", " + place);
  if (on_fixes) {
    mission.nav = translatedTrack(mission.nav, mission.origin_ned_m - origin.ned_m);
  } else {
    mission.nav = trackTurnedToGrid(mission.nav, origin.true_north_bearing_rad);
    mission.crs = origin.crs;
  }
  mission.origin_ned_m = origin.ned_m;
  contents.push_back(
      "origin topic " + t.name + " (" + t.type + "): the first of " + std::to_string(count) +
      " points, on the grid of " + mission.crs +
      (on_fixes ? "" : "; the navigation local to it, turned from true to grid north"));
}

Mission openBag(const std::filesystem::path& path, const OpenOptions& options) {
  std::shared_ptr<const RosBag> bag = openRosBag(path);
  const std::string source = path.string();
  std::vector<std::string> problems = bag->problems();
  const BagTopicKinds kinds(*bag);
  std::vector<std::string> contents = bagTopicLines(*bag, kinds);

  const auto sonar_topic = chooseTopic(*bag, kinds, RosMessageKind::SonarImage,
                                       options.bag.sonar_topic, "--sonar-topic");
  if (!sonar_topic) {
    std::string types;
    for (const BagTopic& t : bag->topics()) {
      types += (types.empty() ? "" : ", ") + t.name + " (" + t.type + ")";
    }
    throw Error(source, "",
                "no sonar topic: expected " + expectedOf(RosMessageKind::SonarImage) +
                    "; the bag has " + (types.empty() ? std::string("no topics") : types));
  }
  requireCdr(*bag, *sonar_topic);
  SonarFrames sonar = kinds.oculus(*sonar_topic)
                          ? indexOculusPings(bag, *sonar_topic, options, problems)
                          : indexSonarImages(bag, *sonar_topic, options, problems);
  contents.push_back("sonar topic " + bag->topics()[*sonar_topic].name + ", frame '" +
                     sonar.frame_id + "', " + std::to_string(sonar.frames.size()) + " frames");
  contents.insert(contents.end(), sonar.notes.begin(), sonar.notes.end());
  contents.push_back(std::string("time: ") + (options.bag.time == BagTime::Header
                                                  ? "header stamps (--time-source header)"
                                                  : "bag receive times (--time-source receive)"));

  std::vector<double> times;
  for (const BagFrameRef& f : sonar.frames) {
    times.push_back(f.time_s);
  }
  Mission mission = recordingMission(path, *sonar.sonar, times, [&](std::size_t k) {
    return bag->messages()[sonar.frames[k].message].place;
  });

  std::string body_frame = "base_link";
  bool body_frd = false;
  if (options.nav_csv.empty()) {
    std::optional<BagNavigation> poses = poseNavigation(*bag, kinds, options, problems);
    if (poses) {
      body_frame = poses->body_frame;
      body_frd = poses->conventions.body_frd;
      contents.push_back(poses->description);
    }
    const auto fix_topic =
        chooseTopic(*bag, kinds, RosMessageKind::GeoFix, options.bag.fix_topic, "--fix-topic");
    if (fix_topic) {
      placeOnFixes(mission, *bag, *fix_topic, poses, options, problems, contents);
    } else if (poses) {
      mission.nav = std::move(poses->track);
      mission.nav_file = path.filename().string() + " topic " + poses->topic;
    } else {
      mission.warnings.push_back(
          "no navigation topic in the bag and no --nav: the vehicle is stationary at the origin "
          "with zero attitude");
    }
    const auto origin_topic = chooseTopic(*bag, kinds, RosMessageKind::GeoOrigin,
                                          options.bag.origin_topic, "--origin-topic");
    if (origin_topic) {
      placeAtGeoOrigin(mission, *bag, *origin_topic, fix_topic.has_value(), problems, contents);
    }
  }
  const auto mounting = bagMounting(staticTransforms(*bag, problems), body_frame, body_frd,
                                    sonar.frame_id, sonar.axes);
  if (mounting) {
    mission.mounting = *mounting;
    contents.push_back("mounting from /tf_static: " + body_frame + " -> " + sonar.frame_id);
  } else if (options.mounting.empty()) {
    mission.warnings.push_back("no /tf_static transform from '" + body_frame + "' to '" +
                               sonar.frame_id +
                               "': the sonar is assumed at the vehicle's origin, looking forward "
                               "(--mounting to give it)");
  }
  for (const std::string& p : problems) {
    mission.warnings.push_back(p);
  }
  mission.contents = std::move(contents);
  applyNavigationAndMounting(mission, options);
  mission.source = std::make_shared<const BagSource>(
      bag, sonar.sonar->id(), std::move(sonar.decode), std::move(sonar.frames));
  return mission;
}

[[maybe_unused]] const bool registered = registerFrameSourceReader(
    {"ros2 bag", [](const std::filesystem::path& path) { return looksLikeRosBag(path); }, openBag});

}  // namespace
}  // namespace sonarcarve
