#include "io/rosbag/bag_writer.h"

#include <sqlite3.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>

#include "common/error.h"
#include "geo/crs.h"
#include "geo/crs_transform.h"
#include "geo/grid_projection.h"
#include "io/files/atomic_file.h"
#include "io/rosbag/bag_geofix.h"
#include "io/rosbag/mcap_writer.h"
#include "io/rosbag/ros_frames.h"

namespace sonarcarve {
namespace {

// A message of a mission's bag: topic 0 sonar, 1 navigation, 2 tf_static.
struct OutMessage {
  std::int64_t stamp_ns = 0;
  BagMessageSpec message;
};

std::int64_t nanoseconds(double seconds) {
  return static_cast<std::int64_t>(std::llround(seconds * 1e9));
}

bool wholeCounts(const cv::Mat& image) {
  for (int r = 0; r < image.rows; ++r) {
    const auto* row = image.ptr<float>(r);
    for (int c = 0; c < image.cols; ++c) {
      if (!(row[c] >= 0.0F && row[c] <= 65535.0F && row[c] == std::floor(row[c]))) {
        return false;
      }
    }
  }
  return true;
}

template <typename T>
void putSample(std::vector<std::uint8_t>& data, std::size_t k, T value) {
  std::memcpy(data.data() + k * sizeof(T), &value, sizeof(T));
}

std::vector<std::uint8_t> imageData(const cv::Mat& image, SonarDtype dtype, ImageLayout layout) {
  const std::size_t size = sonarDtypeSize(static_cast<std::uint32_t>(dtype));
  const auto ranges = static_cast<std::size_t>(image.rows);
  const auto beams = static_cast<std::size_t>(image.cols);
  std::vector<std::uint8_t> data(ranges * beams * size);
  for (std::size_t r = 0; r < ranges; ++r) {
    const auto* row = image.ptr<float>(static_cast<int>(r));
    for (std::size_t b = 0; b < beams; ++b) {
      const std::size_t k = layout == ImageLayout::RangeMajor ? r * beams + b : b * ranges + r;
      const float v = row[b];
      switch (dtype) {
        case SonarDtype::UInt8:
          putSample(data, k, static_cast<std::uint8_t>(std::clamp(std::lround(v), 0L, 255L)));
          break;
        case SonarDtype::UInt16:
          putSample(data, k, static_cast<std::uint16_t>(std::clamp(std::lround(v), 0L, 65535L)));
          break;
        case SonarDtype::Float32:
          putSample(data, k, v);
          break;
        default:
          throw Error("bag writer", "",
                      "dtype " + std::to_string(static_cast<int>(dtype)) +
                          ": the writer writes uint8, uint16 or float32");
      }
    }
  }
  return data;
}

ProjectedSonarImageMsg sonarMessage(const SonarModel& sonar, const BagWriteOptions& options) {
  ProjectedSonarImageMsg msg;
  msg.header.frame_id = options.sonar_frame;
  const BearingTable& bearings = sonar.bearings();
  for (int b = 0; b < sonar.cols(); ++b) {
    msg.beam_directions.push_back(beamDirectionOfBearing(bearings.centre(b), options.axes));
    msg.tx_beamwidths_rad.push_back(static_cast<float>(sonar.verticalAperture()));
    msg.rx_beamwidths_rad.push_back(
        static_cast<float>(bearings.edges()[static_cast<std::size_t>(b) + 1] -
                           bearings.edges()[static_cast<std::size_t>(b)]));
  }
  for (int r = 0; r < sonar.rows(); ++r) {
    msg.ranges_m.push_back(static_cast<float>(sonar.range().centre(r)));
  }
  msg.beam_count = static_cast<std::uint32_t>(sonar.cols());
  return msg;
}

// A mission's navigation samples as WGS84 fixes: the world position (local + origin) on the
// mission's grid back to latitude and longitude by PROJ, and the attitude turned from grid
// north to true north there (the inverse of geo/grid_projection.h's placeOnGrid).
class GeoFixWriter {
 public:
  explicit GeoFixWriter(const Mission& mission)
      : origin_(mission.origin_ned_m),
        to_wgs84_(requireCrs(mission), kWgs84Crs, "bag writer", "crs"),
        grid_(kWgs84Crs, mission.crs, "bag writer", "crs") {}

  NavSatFixMsg fixOf(NavSample& s) const {
    const Eigen::Vector3d world = s.position_m + origin_;
    const auto lon_lat = to_wgs84_.apply({world.y(), world.x(), 0.0});
    if (!lon_lat) {
      throw Error("bag writer", "navigation at t = " + std::to_string(s.time_s) + " s",
                  "PROJ cannot place it in WGS84 (" + to_wgs84_.lastError() +
                      "): expected a position inside the mission's CRS's area");
    }
    const GridProjection::GridPoint p =
        grid_.place(lon_lat->x(), lon_lat->y(), "bag writer", "navigation");
    s.q_world_vehicle =
        Eigen::Quaterniond(Eigen::AngleAxisd(-p.true_north_bearing_rad, Eigen::Vector3d::UnitZ())) *
        s.q_world_vehicle;
    NavSatFixMsg fix;
    fix.latitude_deg = lon_lat->y();
    fix.longitude_deg = lon_lat->x();
    fix.altitude_m = -world.z();
    return fix;
  }

  /// The mission origin (the local zero) in WGS84, and true north's bearing from grid north
  /// there.
  std::pair<GeoPointMsg, double> origin() const {
    NavSample zero;
    const NavSatFixMsg fix = fixOf(zero);  // turns zero's attitude by minus the bearing
    const Eigen::AngleAxisd turn(zero.q_world_vehicle);
    return {{{}, fix.latitude_deg, fix.longitude_deg, fix.altitude_m},
            -turn.angle() * turn.axis().z()};
  }

 private:
  static const std::string& requireCrs(const Mission& mission) {
    if (mission.crs.empty()) {
      throw Error("bag writer", "navigation",
                  "the mission has no CRS: expected one (geodetic navigation or crs: in its "
                  "mission.yaml) to write NavSatFix positions");
    }
    return mission.crs;
  }

  Eigen::Vector3d origin_;
  CrsTransform to_wgs84_;
  GridProjection grid_;
};

std::vector<BagMessageSpec> bagMessages(const Mission& mission, const BagWriteOptions& options,
                                        BagWriteReport& report) {
  std::vector<OutMessage> out;
  ProjectedSonarImageMsg sonar = sonarMessage(mission.sonar, options);
  for (std::size_t i = 0; i < mission.frames.size(); ++i) {
    const Frame frame = loadFrame(mission, i);
    const SonarDtype dtype =
        options.dtype.value_or(wholeCounts(frame.image) ? SonarDtype::UInt16 : SonarDtype::Float32);
    const std::vector<std::uint8_t> data = imageData(frame.image, dtype, options.layout);
    sonar.header.stamp_ns = nanoseconds(mission.frames[i].time_s);
    sonar.dtype = static_cast<std::uint32_t>(dtype);
    sonar.data = data;
    out.push_back({sonar.header.stamp_ns,
                   {0, sonar.header.stamp_ns + nanoseconds(options.receive_delay_s),
                    encodeProjectedSonarImage(sonar)}});
    ++report.frames;
  }
  const RosFrameConventions rep103;
  std::optional<GeoFixWriter> fixes;
  if (!options.fix_topic.empty()) {
    fixes.emplace(mission);
  }
  NavTrack nav = mission.nav;
  if (!options.origin_topic.empty()) {
    auto [origin, bearing] = GeoFixWriter(mission).origin();
    origin.header = {nanoseconds(nav.samples().front().time_s), "map"};
    const std::uint16_t topic = fixes ? 4 : 3;
    out.push_back(
        {origin.header.stamp_ns, {topic, origin.header.stamp_ns, encodeGeoPointStamped(origin)}});
    if (!fixes) {  // the odometry in a frame aligned with true north about the origin
      nav = trackTurnedToGrid(nav, -bearing);
    }
  }
  for (const NavSample& sample : nav.samples()) {
    NavSample s = sample;
    if (fixes) {
      NavSatFixMsg fix = fixes->fixOf(s);  // turns s's attitude to true north
      fix.header = {nanoseconds(s.time_s), "gps"};
      out.push_back({fix.header.stamp_ns, {3, fix.header.stamp_ns, encodeNavSatFix(fix)}});
    }
    const Eigen::Isometry3d T = rosWorldBody(s.T_world_vehicle(), rep103);
    RosPoseMsg pose;
    pose.header = {nanoseconds(s.time_s), "map"};
    pose.child_frame_id = "base_link";
    pose.position = T.translation();
    pose.orientation = Eigen::Quaterniond(T.linear());
    out.push_back({pose.header.stamp_ns, {1, pose.header.stamp_ns, encodeOdometry(pose)}});
    ++report.poses;
  }
  const Eigen::Isometry3d T_body_sonar =
      rosBodySonar(mission.mounting.T_vehicle_sonar(), false, options.axes);
  RosTransformMsg mounting;
  const std::int64_t first =
      out.empty() ? 0 : std::min_element(out.begin(), out.end(), [](const auto& a, const auto& b) {
                          return a.stamp_ns < b.stamp_ns;
                        })->stamp_ns;
  mounting.header = {first, "base_link"};
  mounting.child_frame_id = options.sonar_frame;
  mounting.translation = T_body_sonar.translation();
  mounting.rotation = Eigen::Quaterniond(T_body_sonar.linear());
  out.push_back({first, {2, first, encodeTfMessage({mounting})}});
  std::vector<BagMessageSpec> messages;
  for (OutMessage& m : out) {
    messages.push_back(std::move(m.message));
  }
  return messages;
}

std::vector<BagTopicSpec> topicsOf(const BagWriteOptions& options) {
  std::vector<BagTopicSpec> topics{{options.sonar_topic, kProjectedSonarImageType, ""},
                                   {options.nav_topic, kOdometryType, ""},
                                   {"/tf_static", kTfMessageType, ""}};
  if (!options.fix_topic.empty()) {
    topics.push_back({options.fix_topic, kNavSatFixType, ""});
  }
  if (!options.origin_topic.empty()) {
    topics.push_back({options.origin_topic, kGeoPointStampedType, ""});
  }
  for (BagTopicSpec& t : topics) {
    t.definition = rosMessageDefinition(t.type);
  }
  return topics;
}

void writeMcap(const std::filesystem::path& out, const std::vector<BagTopicSpec>& topics,
               const std::vector<BagMessageSpec>& messages, BagFormat format,
               std::size_t chunk_bytes) {
  const McapChunks chunks = format == BagFormat::McapUnchunked ? McapChunks::None
                            : format == BagFormat::McapLz4     ? McapChunks::Lz4
                            : format == BagFormat::McapNone    ? McapChunks::Uncompressed
                                                               : McapChunks::Zstd;
  McapWriter writer(chunks, chunk_bytes);
  for (std::size_t t = 0; t < topics.size(); ++t) {
    const auto id = static_cast<std::uint16_t>(t + 1);
    const bool schema = !topics[t].type.empty();
    if (schema) {
      writer.addSchema(id, topics[t].type, topics[t].definition);
    }
    writer.addChannel(id, schema ? id : 0, topics[t].name);
  }
  for (const BagMessageSpec& m : messages) {
    writer.addMessage(static_cast<std::uint16_t>(m.topic + 1),
                      static_cast<std::uint64_t>(m.receive_ns),
                      static_cast<std::uint64_t>(m.receive_ns), m.data);
  }
  const std::vector<std::uint8_t> bytes = writer.finish();
  writeFileAtomically(out, {reinterpret_cast<const char*>(bytes.data()), bytes.size()});
}

void sqlite(sqlite3* db, const char* sql, const std::filesystem::path& out) {
  char* message = nullptr;
  if (sqlite3_exec(db, sql, nullptr, nullptr, &message) != SQLITE_OK) {
    const std::string why = message != nullptr ? message : "unknown error";
    sqlite3_free(message);
    throw Error(out.string(), "", "SQLite: " + why);
  }
}

void writeDb3(const std::filesystem::path& out, const std::vector<BagTopicSpec>& topics,
              const std::vector<BagMessageSpec>& messages) {
  // As writeFileAtomically: onto a regular file or a new path, through a symbolic link.
  const std::filesystem::path target = outputFileTarget(out);
  const std::filesystem::path temporary =
      target.parent_path() /
      ("." + target.filename().string() + ".tmp-" + std::to_string(::getpid()));
  std::filesystem::remove(temporary);
  sqlite3* db = nullptr;
  sqlite3_stmt* insert = nullptr;
  try {
    if (sqlite3_open(temporary.c_str(), &db) != SQLITE_OK) {
      throw Error(out.string(), "", std::string("SQLite: cannot create: ") + sqlite3_errmsg(db));
    }
    sqlite(db,
           "CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT NULL, "
           "serialization_format TEXT NOT NULL, offered_qos_profiles TEXT NOT NULL);"
           "CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id INTEGER NOT NULL, "
           "timestamp INTEGER NOT NULL, data BLOB NOT NULL);"
           "CREATE INDEX timestamp_idx ON messages (timestamp ASC);"
           "BEGIN TRANSACTION;",
           out);
    for (std::size_t t = 0; t < topics.size(); ++t) {
      const std::string sql = "INSERT INTO topics VALUES(" + std::to_string(t + 1) + ", '" +
                              topics[t].name + "', '" + topics[t].type + "', 'cdr', '')";
      sqlite(db, sql.c_str(), out);
    }
    sqlite3_prepare_v2(db, "INSERT INTO messages(topic_id, timestamp, data) VALUES(?, ?, ?)", -1,
                       &insert, nullptr);
    for (const BagMessageSpec& m : messages) {
      sqlite3_reset(insert);
      sqlite3_bind_int64(insert, 1, static_cast<sqlite3_int64>(m.topic + 1));
      sqlite3_bind_int64(insert, 2, m.receive_ns);
      sqlite3_bind_blob(insert, 3, m.data.data(), static_cast<int>(m.data.size()), SQLITE_STATIC);
      if (sqlite3_step(insert) != SQLITE_DONE) {
        throw Error(out.string(), "", std::string("SQLite: ") + sqlite3_errmsg(db));
      }
    }
    sqlite3_finalize(insert);
    insert = nullptr;
    sqlite(db, "COMMIT;", out);
    if (sqlite3_close(db) != SQLITE_OK) {
      throw Error(out.string(), "", "SQLite: cannot close the file");
    }
    db = nullptr;
    std::filesystem::rename(temporary, target);
  } catch (...) {
    sqlite3_finalize(insert);
    sqlite3_close(db);
    std::error_code ec;
    std::filesystem::remove(temporary, ec);
    throw;
  }
}

}  // namespace

BagWriteReport writeRosBag(const Mission& mission, const std::filesystem::path& out,
                           const BagWriteOptions& options) {
  if (options.axes == SonarAxes::Auto) {
    throw Error("bag writer", "", "sonar axes must be z-forward or x-forward, not auto");
  }
  BagWriteReport report;
  writeBagMessages(out, options.format, topicsOf(options), bagMessages(mission, options, report),
                   options.chunk_bytes);
  return report;
}

void writeBagMessages(const std::filesystem::path& out, BagFormat format,
                      const std::vector<BagTopicSpec>& topics, std::vector<BagMessageSpec> messages,
                      std::size_t chunk_bytes) {
  std::stable_sort(
      messages.begin(), messages.end(),
      [](const BagMessageSpec& a, const BagMessageSpec& b) { return a.receive_ns < b.receive_ns; });
  if (!messages.empty() && messages.front().receive_ns < 0) {
    throw Error("bag writer", "",
                "a time before 0 s: expected times from 0 (a bag's receive times are unsigned)");
  }
  if (format == BagFormat::Db3) {
    writeDb3(out, topics, messages);
  } else {
    writeMcap(out, topics, messages, format, chunk_bytes);
  }
}

}  // namespace sonarcarve
