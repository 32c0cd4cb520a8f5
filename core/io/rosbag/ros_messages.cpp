#include "io/rosbag/ros_messages.h"

#include <cmath>
#include <map>

#include "common/error.h"
#include "io/rosbag/cdr.h"

namespace sonarcarve {
namespace {

// Field lists of the messages (ros2msg syntax, without comments).
const std::map<std::string, std::string>& fieldLists() {
  static const std::map<std::string, std::string> fields = {
      {"marine_acoustic_msgs/ProjectedSonarImage",
       "std_msgs/Header header\nPingInfo ping_info\ngeometry_msgs/Vector3[] beam_directions\n"
       "float32[] ranges\nSonarImageData image\n"},
      {"marine_acoustic_msgs/PingInfo",
       "float32 frequency\nfloat32 sound_speed\nfloat32[] tx_beamwidths\n"
       "float32[] rx_beamwidths\n"},
      {"marine_acoustic_msgs/SonarImageData",
       "bool is_bigendian\nuint32 DTYPE_UINT8 = 0\nuint32 DTYPE_UINT16 = 2\n"
       "uint32 DTYPE_FLOAT32 = 8\nuint32 dtype\nuint32 beam_count\nuint8[] data\n"},
      {"std_msgs/Header", "builtin_interfaces/Time stamp\nstring frame_id\n"},
      {"builtin_interfaces/Time", "int32 sec\nuint32 nanosec\n"},
      {"geometry_msgs/Vector3", "float64 x\nfloat64 y\nfloat64 z\n"},
      {"geometry_msgs/Point", "float64 x\nfloat64 y\nfloat64 z\n"},
      {"geometry_msgs/Quaternion", "float64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n"},
      {"geometry_msgs/Pose", "Point position\nQuaternion orientation\n"},
      {"geometry_msgs/PoseWithCovariance", "Pose pose\nfloat64[36] covariance\n"},
      {"geometry_msgs/Twist", "Vector3 linear\nVector3 angular\n"},
      {"geometry_msgs/TwistWithCovariance", "Twist twist\nfloat64[36] covariance\n"},
      {"geometry_msgs/Transform", "Vector3 translation\nQuaternion rotation\n"},
      {"geometry_msgs/TransformStamped",
       "std_msgs/Header header\nstring child_frame_id\nTransform transform\n"},
      {"nav_msgs/Odometry",
       "std_msgs/Header header\nstring child_frame_id\ngeometry_msgs/PoseWithCovariance pose\n"
       "geometry_msgs/TwistWithCovariance twist\n"},
      {"tf2_msgs/TFMessage", "geometry_msgs/TransformStamped[] transforms\n"},
      {"sensor_msgs/NavSatFix",
       "std_msgs/Header header\nNavSatStatus status\nfloat64 latitude\nfloat64 longitude\n"
       "float64 altitude\nfloat64[9] position_covariance\n"
       "uint8 COVARIANCE_TYPE_UNKNOWN = 0\nuint8 COVARIANCE_TYPE_APPROXIMATED = 1\n"
       "uint8 COVARIANCE_TYPE_DIAGONAL_KNOWN = 2\nuint8 COVARIANCE_TYPE_KNOWN = 3\n"
       "uint8 position_covariance_type\n"},
      {"geographic_msgs/GeoPoint", "float64 latitude\nfloat64 longitude\nfloat64 altitude\n"},
      {"geographic_msgs/GeoPointStamped", "std_msgs/Header header\nGeoPoint position\n"},
      {"sensor_msgs/NavSatStatus",
       "int8 STATUS_NO_FIX = -1\nint8 STATUS_FIX = 0\nint8 STATUS_SBAS_FIX = 1\n"
       "int8 STATUS_GBAS_FIX = 2\nint8 status\nuint16 SERVICE_GPS = 1\n"
       "uint16 SERVICE_GLONASS = 2\nuint16 SERVICE_COMPASS = 4\nuint16 SERVICE_GALILEO = 8\n"
       "uint16 service\n"},
  };
  return fields;
}

// Dependencies of each top-level type, in the order ROS 2 lists them.
const std::map<std::string, std::vector<std::string>>& dependencies() {
  static const std::map<std::string, std::vector<std::string>> deps = {
      {"marine_acoustic_msgs/ProjectedSonarImage",
       {"std_msgs/Header", "builtin_interfaces/Time", "marine_acoustic_msgs/PingInfo",
        "geometry_msgs/Vector3", "marine_acoustic_msgs/SonarImageData"}},
      {"nav_msgs/Odometry",
       {"std_msgs/Header", "builtin_interfaces/Time", "geometry_msgs/PoseWithCovariance",
        "geometry_msgs/Pose", "geometry_msgs/Point", "geometry_msgs/Quaternion",
        "geometry_msgs/TwistWithCovariance", "geometry_msgs/Twist", "geometry_msgs/Vector3"}},
      {"sensor_msgs/NavSatFix",
       {"std_msgs/Header", "builtin_interfaces/Time", "sensor_msgs/NavSatStatus"}},
      {"geographic_msgs/GeoPointStamped",
       {"std_msgs/Header", "builtin_interfaces/Time", "geographic_msgs/GeoPoint"}},
      {"tf2_msgs/TFMessage",
       {"geometry_msgs/TransformStamped", "std_msgs/Header", "builtin_interfaces/Time",
        "geometry_msgs/Transform", "geometry_msgs/Vector3", "geometry_msgs/Quaternion"}},
  };
  return deps;
}

// "pkg/msg/Type" or "pkg/Type" -> "pkg/Type".
std::string shortType(std::string_view type) {
  std::string t(type);
  const auto at = t.find("/msg/");
  return at == std::string::npos ? t : t.substr(0, at) + t.substr(at + 4);
}

}  // namespace

RosHeader readRosHeader(CdrReader& in) {
  RosHeader header;
  const auto sec = in.read<std::int32_t>("header.stamp.sec");
  const auto nanosec = in.read<std::uint32_t>("header.stamp.nanosec");
  if (nanosec >= 1000000000U) {
    in.fail("header.stamp.nanosec " + std::to_string(nanosec) + ": expected below 10^9");
  }
  header.stamp_ns = static_cast<std::int64_t>(sec) * 1000000000 + nanosec;
  header.frame_id = in.readString("header.frame_id");
  return header;
}

namespace {

Eigen::Vector3d readVector3(CdrReader& in, const char* what) {
  const double x = in.read<double>(what);
  const double y = in.read<double>(what);
  const double z = in.read<double>(what);
  return {x, y, z};
}

Eigen::Quaterniond readQuaternion(CdrReader& in, const char* what) {
  const double x = in.read<double>(what);
  const double y = in.read<double>(what);
  const double z = in.read<double>(what);
  const double w = in.read<double>(what);
  const Eigen::Quaterniond q(w, x, y, z);
  const double norm = q.norm();
  if (!std::isfinite(norm) || std::abs(norm - 1.0) > 1e-3) {
    in.fail(std::string(what) + " has norm " + std::to_string(norm) +
            ": expected a unit quaternion");
  }
  return q.normalized();
}

void skipCovariance(CdrReader& in, const char* what) {
  for (int i = 0; i < 36; ++i) {
    in.read<double>(what);
  }
}

void writeHeader(CdrWriter& out, const RosHeader& header) {
  // Floor division: stamps before 1970 have a negative second and a positive nanosecond.
  std::int64_t sec = header.stamp_ns / 1000000000;
  std::int64_t nanosec = header.stamp_ns % 1000000000;
  if (nanosec < 0) {
    nanosec += 1000000000;
    sec -= 1;
  }
  out.write(static_cast<std::int32_t>(sec));
  out.write(static_cast<std::uint32_t>(nanosec));
  out.writeString(header.frame_id);
}

void writeVector3(CdrWriter& out, const Eigen::Vector3d& v) {
  out.write(v.x());
  out.write(v.y());
  out.write(v.z());
}

void writeQuaternion(CdrWriter& out, const Eigen::Quaterniond& q) {
  out.write(q.x());
  out.write(q.y());
  out.write(q.z());
  out.write(q.w());
}

// latitude, longitude, altitude: NavSatFix's and GeoPoint's.
void writeLatLonAlt(CdrWriter& out, double latitude, double longitude, double altitude) {
  out.write(latitude);
  out.write(longitude);
  out.write(altitude);
}

void writeZeros(CdrWriter& out, int count) {
  for (int i = 0; i < count; ++i) {
    out.write(0.0);
  }
}

}  // namespace

bool isLegacySonarImage(std::string_view type) {
  return shortType(type) == "acoustic_msgs/SonarImage";
}

RosMessageKind rosMessageKind(std::string_view type) {
  const std::string t = shortType(type);
  if (t == "marine_acoustic_msgs/ProjectedSonarImage" || t == "acoustic_msgs/ProjectedSonarImage" ||
      isLegacySonarImage(t)) {
    return RosMessageKind::SonarImage;
  }
  if (t == "nav_msgs/Odometry" || t == "geometry_msgs/PoseStamped" ||
      t == "geometry_msgs/PoseWithCovarianceStamped") {
    return RosMessageKind::VehiclePose;
  }
  if (t == "tf2_msgs/TFMessage") {
    return RosMessageKind::Transforms;
  }
  if (t == "sensor_msgs/NavSatFix") {
    return RosMessageKind::GeoFix;
  }
  if (t == "geographic_msgs/GeoPoint" || t == "geographic_msgs/GeoPointStamped") {
    return RosMessageKind::GeoOrigin;
  }
  return RosMessageKind::Other;
}

std::string canonicalRosType(std::string_view type) {
  const std::string t = shortType(type);
  const auto slash = t.find('/');
  return slash == std::string::npos ? t : t.substr(0, slash) + "/msg" + t.substr(slash);
}

std::size_t sonarDtypeSize(std::uint32_t dtype) {
  switch (static_cast<SonarDtype>(dtype)) {
    case SonarDtype::UInt8:
    case SonarDtype::Int8:
      return 1;
    case SonarDtype::UInt16:
    case SonarDtype::Int16:
      return 2;
    case SonarDtype::UInt32:
    case SonarDtype::Int32:
    case SonarDtype::Float32:
      return 4;
    case SonarDtype::UInt64:
    case SonarDtype::Int64:
    case SonarDtype::Float64:
      return 8;
  }
  return 0;
}

RosHeader decodeRosHeader(std::span<const std::uint8_t> cdr, const std::string& source,
                          const std::string& place) {
  CdrReader in(cdr, source, place);
  return readRosHeader(in);
}

ProjectedSonarImageMsg decodeProjectedSonarImage(std::span<const std::uint8_t> cdr,
                                                 const std::string& source,
                                                 const std::string& place) {
  CdrReader in(cdr, source, place);
  ProjectedSonarImageMsg msg;
  msg.header = readRosHeader(in);
  msg.frequency_hz = in.read<float>("ping_info.frequency");
  msg.sound_speed_mps = in.read<float>("ping_info.sound_speed");
  msg.tx_beamwidths_rad = in.readSequence<float>("ping_info.tx_beamwidths");
  msg.rx_beamwidths_rad = in.readSequence<float>("ping_info.rx_beamwidths");
  const std::uint32_t beams = in.readCount(24, "beam_directions");
  msg.beam_directions.reserve(beams);
  for (std::uint32_t b = 0; b < beams; ++b) {
    msg.beam_directions.push_back(readVector3(in, "beam_directions"));
  }
  msg.ranges_m = in.readSequence<float>("ranges");
  msg.is_bigendian = in.readBool("image.is_bigendian");
  msg.dtype = in.read<std::uint32_t>("image.dtype");
  msg.beam_count = in.read<std::uint32_t>("image.beam_count");
  const std::uint32_t size = in.readCount(1, "image.data");
  msg.data = in.readBytes(size, "image.data");
  in.requireEnd(7, kProjectedSonarImageType);
  return msg;
}

ProjectedSonarImageMsg decodeLegacySonarImage(std::span<const std::uint8_t> cdr,
                                              const std::string& source, const std::string& place) {
  CdrReader in(cdr, source, place);
  ProjectedSonarImageMsg msg;
  msg.header = readRosHeader(in);
  msg.frequency_hz = in.read<float>("frequency");
  msg.sound_speed_mps = in.read<float>("sound_speed");
  msg.rx_beamwidths_rad = {in.read<float>("azimuth_beamwidth")};
  msg.tx_beamwidths_rad = {in.read<float>("elevation_beamwidth")};
  for (const float azimuth : in.readSequence<float>("azimuth_angles")) {
    msg.beam_directions.emplace_back(std::cos(azimuth), std::sin(azimuth), 0.0);
  }
  in.readSequence<float>("elevation_angles");
  msg.ranges_m = in.readSequence<float>("ranges");
  msg.is_bigendian = in.readBool("is_bigendian");
  const auto data_size = in.read<std::uint8_t>("data_size");
  if (data_size != 1 && data_size != 2 && data_size != 4) {
    in.fail("data_size " + std::to_string(data_size) + ": expected 1, 2 or 4 bytes");
  }
  msg.dtype = static_cast<std::uint32_t>(data_size == 1   ? SonarDtype::UInt8
                                         : data_size == 2 ? SonarDtype::UInt16
                                                          : SonarDtype::UInt32);
  msg.beam_count = static_cast<std::uint32_t>(msg.beam_directions.size());
  const std::uint32_t size = in.readCount(1, "intensities");
  msg.data = in.readBytes(size, "intensities");
  in.requireEnd(7, "acoustic_msgs/msg/SonarImage");
  return msg;
}

ProjectedSonarImageMsg decodeSonarImage(std::string_view type, std::span<const std::uint8_t> cdr,
                                        const std::string& source, const std::string& place) {
  return isLegacySonarImage(type) ? decodeLegacySonarImage(cdr, source, place)
                                  : decodeProjectedSonarImage(cdr, source, place);
}

RosPoseMsg decodeRosPose(std::string_view type, std::span<const std::uint8_t> cdr,
                         const std::string& source, const std::string& place) {
  const std::string t = shortType(type);
  CdrReader in(cdr, source, place);
  RosPoseMsg msg;
  msg.header = readRosHeader(in);
  if (t == "nav_msgs/Odometry") {
    msg.child_frame_id = in.readString("child_frame_id");
  } else if (t != "geometry_msgs/PoseStamped" && t != "geometry_msgs/PoseWithCovarianceStamped") {
    throw Error(source, place,
                "type " + std::string(type) +
                    ": expected nav_msgs/msg/Odometry, geometry_msgs/msg/PoseStamped or "
                    "geometry_msgs/msg/PoseWithCovarianceStamped");
  }
  msg.position = readVector3(in, "pose.position");
  msg.orientation = readQuaternion(in, "pose.orientation");
  if (t != "geometry_msgs/PoseStamped") {
    skipCovariance(in, "pose.covariance");
  }
  if (!msg.position.allFinite()) {
    in.fail("pose.position is not finite: expected metres");
  }
  return msg;
}

NavSatFixMsg decodeNavSatFix(std::span<const std::uint8_t> cdr, const std::string& source,
                             const std::string& place) {
  CdrReader in(cdr, source, place);
  NavSatFixMsg msg;
  msg.header = readRosHeader(in);
  msg.status = in.read<std::int8_t>("status.status");
  msg.service = in.read<std::uint16_t>("status.service");
  msg.latitude_deg = in.read<double>("latitude");
  msg.longitude_deg = in.read<double>("longitude");
  msg.altitude_m = in.read<double>("altitude");
  for (int i = 0; i < 9; ++i) {
    in.read<double>("position_covariance");
  }
  in.read<std::uint8_t>("position_covariance_type");
  return msg;
}

GeoPointMsg decodeGeoPoint(std::string_view type, std::span<const std::uint8_t> cdr,
                           const std::string& source, const std::string& place) {
  CdrReader in(cdr, source, place);
  GeoPointMsg msg;
  if (shortType(type) == "geographic_msgs/GeoPointStamped") {
    msg.header = readRosHeader(in);
  }
  msg.latitude_deg = in.read<double>("latitude");
  msg.longitude_deg = in.read<double>("longitude");
  msg.altitude_m = in.read<double>("altitude");
  return msg;
}

std::vector<RosTransformMsg> decodeTfMessage(std::span<const std::uint8_t> cdr,
                                             const std::string& source, const std::string& place) {
  CdrReader in(cdr, source, place);
  // A transform takes at least 8 (stamp) + 4 + 4 (two empty strings) + 56 bytes.
  const std::uint32_t count = in.readCount(72, "transforms");
  std::vector<RosTransformMsg> out(count);
  for (RosTransformMsg& t : out) {
    t.header = readRosHeader(in);
    t.child_frame_id = in.readString("child_frame_id");
    t.translation = readVector3(in, "transform.translation");
    t.rotation = readQuaternion(in, "transform.rotation");
    if (!t.translation.allFinite()) {
      in.fail("transform.translation is not finite: expected metres");
    }
  }
  return out;
}

std::vector<std::uint8_t> encodeProjectedSonarImage(const ProjectedSonarImageMsg& msg) {
  CdrWriter out;
  writeHeader(out, msg.header);
  out.write(msg.frequency_hz);
  out.write(msg.sound_speed_mps);
  out.writeSequence(msg.tx_beamwidths_rad);
  out.writeSequence(msg.rx_beamwidths_rad);
  out.writeCount(msg.beam_directions.size());
  for (const Eigen::Vector3d& d : msg.beam_directions) {
    writeVector3(out, d);
  }
  out.writeSequence(msg.ranges_m);
  out.writeBool(msg.is_bigendian);
  out.write(msg.dtype);
  out.write(msg.beam_count);
  out.writeCount(msg.data.size());
  out.writeBytes(msg.data);
  return out.bytes();
}

std::vector<std::uint8_t> encodeOdometry(const RosPoseMsg& msg) {
  CdrWriter out;
  writeHeader(out, msg.header);
  out.writeString(msg.child_frame_id);
  writeVector3(out, msg.position);
  writeQuaternion(out, msg.orientation);
  writeZeros(out, 36);      // pose covariance
  writeZeros(out, 6 + 36);  // twist and its covariance
  return out.bytes();
}

std::vector<std::uint8_t> encodeNavSatFix(const NavSatFixMsg& msg) {
  CdrWriter out;
  writeHeader(out, msg.header);
  out.write(msg.status);
  out.write(msg.service);
  writeLatLonAlt(out, msg.latitude_deg, msg.longitude_deg, msg.altitude_m);
  writeZeros(out, 9);
  out.write(std::uint8_t{0});
  return out.bytes();
}

std::vector<std::uint8_t> encodeGeoPointStamped(const GeoPointMsg& msg) {
  CdrWriter out;
  writeHeader(out, msg.header);
  writeLatLonAlt(out, msg.latitude_deg, msg.longitude_deg, msg.altitude_m);
  return out.bytes();
}

std::vector<std::uint8_t> encodeTfMessage(const std::vector<RosTransformMsg>& transforms) {
  CdrWriter out;
  out.writeCount(transforms.size());
  for (const RosTransformMsg& t : transforms) {
    writeHeader(out, t.header);
    out.writeString(t.child_frame_id);
    writeVector3(out, t.translation);
    writeQuaternion(out, t.rotation);
  }
  return out.bytes();
}

std::string rosMessageDefinition(std::string_view type) {
  const std::string t = shortType(type);
  const auto& fields = fieldLists();
  const auto top = fields.find(t);
  if (top == fields.end()) {
    throw Error("bag writer", "", "no built-in definition of " + std::string(type));
  }
  std::string text = top->second;
  const auto deps = dependencies().find(t);
  if (deps != dependencies().end()) {
    for (const std::string& dep : deps->second) {
      text += std::string(80, '=') + "\nMSG: " + dep + "\n" + fields.at(dep);
    }
  }
  return text;
}

}  // namespace sonarcarve
