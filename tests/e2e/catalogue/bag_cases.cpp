// Class "ROS 2 bags": the example mission written as a bag (MCAP with zstd chunks, or
// SQLite3), then cut short, emptied, reduced to its magic, or asked for a topic it does not
// hold. A bag cut inside a record keeps every record before it and says where reading
// stopped; nothing is written when no frame can be read.
#include <limits>
#include <utility>

#include "e2e/catalogue/catalogue.h"
#include "io/mission/mission.h"
#include "io/rosbag/bag_writer.h"
#include "io/rosbag/ros_bag.h"

namespace sonarcarve::test {
namespace {

// The example mission as a bag at `file` under the workspace.
std::string exampleBag(const Workspace& ws, const std::string& file, BagFormat format) {
  BagWriteOptions options;
  options.format = format;
  writeRosBag(readMission(ws.mission()), ws / file, options);
  return readText(ws / file);
}

// A bag of the example mission, its bytes changed by `change`, then `args`.
CatalogueCase bagCase(const std::string& name, BagFormat format, const std::string& file,
                      std::function<std::string(std::string)> change, const std::string& args,
                      Outcome outcome, std::vector<std::string> message,
                      std::vector<std::string> absent = {}) {
  return {.name = name,
          .prepare =
              [=](const Workspace& ws) {
                writeBytes(ws / file, change(exampleBag(ws, file, format)));
                return args;
              },
          .outcome = outcome,
          .message = std::move(message),
          .absent = std::move(absent)};
}

std::string unchanged(std::string bytes) {
  return bytes;
}

// The example mission on a transverse Mercator grid centred on 43 N, 3 E (crs: in its
// mission.yaml) as bag.mcap with its positions as sensor_msgs/NavSatFix on /fix, fix k changed
// by `change` (issue 43), and, given `origin`, its origin as a GeoPointStamped on /origin
// changed by it. The bag's reader places the fixes on their UTM zone, 31N.
using FixChange = std::function<void(NavSatFixMsg&, std::size_t)>;
using OriginChange = std::function<void(GeoPointMsg&)>;
void writeFixBag(const Workspace& ws, const FixChange& change, const OriginChange& origin = {}) {
  writeBytes(ws.mission() / "mission.yaml",
             readText(ws.mission() / "mission.yaml") +
                 "crs: +proj=tmerc +lat_0=43 +lon_0=3 +k=1 +x_0=0 +y_0=0 +datum=WGS84 "
                 "+units=m +type=crs\n");
  BagWriteOptions options;
  options.fix_topic = "/fix";
  options.origin_topic = origin ? "/origin" : "";
  writeRosBag(readMission(ws.mission()), ws / "plain.mcap", options);
  const std::unique_ptr<RosBag> bag = openRosBag(ws / "plain.mcap");
  std::vector<BagTopicSpec> topics;
  for (const BagTopic& t : bag->topics()) {
    topics.push_back({t.name, t.type, rosMessageDefinition(t.type)});
  }
  std::vector<BagMessageSpec> messages;
  std::size_t k = 0;
  for (const BagMessage& m : bag->messages()) {
    std::vector<std::uint8_t> data = bag->payload(m);
    if (rosMessageKind(bag->topics()[m.topic].type) == RosMessageKind::GeoFix) {
      NavSatFixMsg fix = decodeNavSatFix(data, "plain.mcap", m.place);
      change(fix, k++);
      data = encodeNavSatFix(fix);
    } else if (rosMessageKind(bag->topics()[m.topic].type) == RosMessageKind::GeoOrigin) {
      GeoPointMsg point = decodeGeoPoint(bag->topics()[m.topic].type, data, "plain.mcap", m.place);
      origin(point);
      data = encodeGeoPointStamped(point);
    }
    messages.push_back({m.topic, m.receive_ns, std::move(data)});
  }
  writeBagMessages(ws / "bag.mcap", BagFormat::Mcap, topics, std::move(messages));
}

CatalogueCase fixCase(const std::string& name, FixChange change, const std::string& args,
                      Outcome outcome, std::vector<std::string> message,
                      std::vector<std::string> absent = {}) {
  return {.name = name,
          .prepare =
              [=](const Workspace& ws) {
                writeFixBag(ws, change);
                return args;
              },
          .outcome = outcome,
          .message = std::move(message),
          .absent = std::move(absent)};
}

}  // namespace

std::vector<CatalogueCase> bagCases() {
  return {
      // NavSatFix positions (issue 43): read with their CRS; fixes without a fix or with NaN
      // are left out and counted; none left is an error saying why.
      fixCase("NavSatFixGivesTheGrid", [](NavSatFixMsg&, std::size_t) {}, "info bag.mcap",
              Outcome::Succeeds, {"position topic /fix (sensor_msgs/NavSatFix)", "EPSG:32631"}),
      fixCase("NavSatFixWithNaN",
              [](NavSatFixMsg& f, std::size_t k) {
                if (k % 3 == 1)
                  f.latitude_deg = std::numeric_limits<double>::quiet_NaN();
              },
              "info bag.mcap", Outcome::Succeeds,
              {"topic /fix: fixes left out:", "with a latitude, longitude or altitude not finite"}),
      // A flag naming a topic of another kind says what that flag needs (--fix-topic on the
      // Odometry was told it expected an Odometry).
      fixCase("FixTopicOfAnotherType", [](NavSatFixMsg&, std::size_t) {},
              "info bag.mcap --fix-topic /odometry", Outcome::Fails,
              {"bag.mcap: topic /odometry: type nav_msgs/msg/Odometry (--fix-topic): expected "
               "sensor_msgs/msg/NavSatFix"}),
      fixCase("NavSatFixAllWithoutAFix",
              [](NavSatFixMsg& f, std::size_t) { f.status = kNavSatStatusNoFix; },
              "reconstruct bag.mcap --out out", Outcome::Fails,
              {"bag.mcap: topic /fix: no usable sensor_msgs/NavSatFix of",
               "with status STATUS_NO_FIX", "expected fixes with finite latitude"},
              {"out"}),
      // A GeoPointStamped origin (issue 43): the mission origin; one off the Earth is refused.
      {.name = "GeoPointGivesTheOrigin",
       .prepare =
           [](const Workspace& ws) {
             writeFixBag(
                 ws, [](NavSatFixMsg&, std::size_t) {}, [](GeoPointMsg&) {});
             return std::string("info bag.mcap");
           },
       .outcome = Outcome::Succeeds,
       .message = {"origin topic /origin (geographic_msgs/msg/GeoPointStamped): the first of 1 "
                   "points, on the grid of EPSG:32631"}},
      {.name = "GeoPointOffTheEarth",
       .prepare =
           [](const Workspace& ws) {
             writeFixBag(
                 ws, [](NavSatFixMsg&, std::size_t) {},
                 [](GeoPointMsg& p) { p.latitude_deg = 95.0; });
             return std::string("reconstruct bag.mcap --out out");
           },
       .message = {"bag.mcap: topic /origin, message", "latitude 95",
                   "expected finite WGS84 degrees within -90..90"},
       .absent = {"out"}},
      bagCase("McapReadsAndReconstructs", BagFormat::Mcap, "bag.mcap", unchanged,
              "reconstruct bag.mcap --mesh false --out out", Outcome::Succeeds, {"denoising:"}),
      bagCase("McapInfoListsTheTopics", BagFormat::Mcap, "bag.mcap", unchanged, "info bag.mcap",
              Outcome::Succeeds,
              {"ROS 2 bag", "marine_acoustic_msgs/msg/ProjectedSonarImage, 10 messages",
               "nav_msgs/msg/Odometry"}),
      bagCase("Db3ReadsAndReconstructs", BagFormat::Db3, "bag.db3", unchanged,
              "reconstruct bag.db3 --mesh false --out out", Outcome::Succeeds, {"denoising:"}),
      // Cut inside the message definitions: no topics at all.
      bagCase("McapCutInItsSchemas", BagFormat::Mcap, "bag.mcap",
              [](std::string b) { return b.substr(0, 400); }, "reconstruct bag.mcap --out out",
              Outcome::Fails,
              {"bag.mcap: byte 8: no Channel record", "cut short or corrupt; reading stopped"},
              {"out"}),
      // Cut inside the one chunk that holds every image.
      bagCase("McapCutInsideItsImages", BagFormat::Mcap, "bag.mcap",
              [](std::string b) { return b.substr(0, b.size() / 2); },
              "reconstruct bag.mcap --out out", Outcome::Fails,
              {"bag.mcap", "no readable sonar message", "cut short or corrupt; reading stopped"},
              {"out"}),
      // Messages in the data section, cut after the sixth image: the first frames are kept,
      // and the rest is reported.
      bagCase("McapUnchunkedCutShortKeepsItsFirstFrames", BagFormat::McapUnchunked, "bag.mcap",
              [](std::string b) { return b.substr(0, b.size() * 6 / 10); }, "info bag.mcap",
              Outcome::Succeeds, {"bag.mcap", "reading stopped", "Frames       "}),
      bagCase("McapEmpty", BagFormat::Mcap, "bag.mcap", [](const std::string&) { return ""; },
              "info bag.mcap", Outcome::Fails,
              {"bag.mcap", "not a recording this build reads", "ros2 bag"}),
      bagCase("McapMagicOnly", BagFormat::Mcap, "bag.mcap",
              [](std::string b) { return b.substr(0, 8); }, "info bag.mcap", Outcome::Fails,
              {"bag.mcap: byte 8", "expected the Header record"}),
      bagCase("McapUnknownSonarTopic", BagFormat::Mcap, "bag.mcap", unchanged,
              "reconstruct bag.mcap --sonar-topic /nope --out out", Outcome::Fails,
              {"bag.mcap", "no topic /nope (--sonar-topic)", "sonar topics: /sonar/image"},
              {"out"}),
      bagCase("Db3Garbage", BagFormat::Db3, "bag.db3",
              [](const std::string&) { return std::string("SQLite format 3\0garbage", 23); },
              "info bag.db3", Outcome::Fails, {"bag.db3", "not a recording this build reads"}),
  };
}

}  // namespace sonarcarve::test
