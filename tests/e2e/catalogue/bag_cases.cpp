// Class "ROS 2 bags": the example mission written as a bag (MCAP with zstd chunks, or
// SQLite3), then cut short, emptied, reduced to its magic, or asked for a topic it does not
// hold. A bag cut inside a record keeps every record before it and says where reading
// stopped; nothing is written when no frame can be read.
#include <utility>

#include "e2e/catalogue/catalogue.h"
#include "io/mission/mission.h"
#include "io/rosbag/bag_writer.h"

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

}  // namespace

std::vector<CatalogueCase> bagCases() {
  return {
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
