// The ROS 2 messages SonarCarve reads from bags, with built-in definitions (by type name: bags
// stored in SQLite3 often carry none) and their CDR layout (io/rosbag/cdr.h):
//   marine_acoustic_msgs/msg/ProjectedSonarImage (also under the older package name
//     acoustic_msgs): sonar images;
//   nav_msgs/msg/Odometry, geometry_msgs/msg/PoseStamped and PoseWithCovarianceStamped: the
//     vehicle's pose;
//   tf2_msgs/msg/TFMessage: transforms (the sonar's mounting, from /tf_static);
//   sensor_msgs/msg/NavSatFix: the vehicle's WGS84 position (io/rosbag/bag_geofix.h);
//   geographic_msgs/msg/GeoPoint and GeoPointStamped: the mission origin (WGS84).
// Decoding checks every length against the bytes left and throws Error naming the file, the
// message and the CDR byte. Encoding (for the bag writer) writes little-endian CDR.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace sonarcarve {

/// What a message type is to SonarCarve.
enum class RosMessageKind { Other, SonarImage, VehiclePose, Transforms, GeoFix, GeoOrigin };

/// True for the older acoustic_msgs/msg/SonarImage (azimuths instead of beam directions).
bool isLegacySonarImage(std::string_view type);

/// The kind of a type name, with or without "/msg/" ("nav_msgs/msg/Odometry",
/// "nav_msgs/Odometry").
RosMessageKind rosMessageKind(std::string_view type);
/// The type name with "/msg/" ("nav_msgs/Odometry" -> "nav_msgs/msg/Odometry").
std::string canonicalRosType(std::string_view type);

inline constexpr const char* kProjectedSonarImageType =
    "marine_acoustic_msgs/msg/ProjectedSonarImage";
inline constexpr const char* kOdometryType = "nav_msgs/msg/Odometry";
inline constexpr const char* kTfMessageType = "tf2_msgs/msg/TFMessage";
inline constexpr const char* kNavSatFixType = "sensor_msgs/msg/NavSatFix";
inline constexpr const char* kGeoPointStampedType = "geographic_msgs/msg/GeoPointStamped";

struct RosHeader {
  std::int64_t stamp_ns = 0;  ///< builtin_interfaces/Time as nanoseconds
  std::string frame_id;
};

/// SonarImageData.dtype values.
enum class SonarDtype : std::uint32_t {
  UInt8 = 0,
  Int8 = 1,
  UInt16 = 2,
  Int16 = 3,
  UInt32 = 4,
  Int32 = 5,
  UInt64 = 6,
  Int64 = 7,
  Float32 = 8,
  Float64 = 9
};
/// Bytes per sample of a dtype, 0 if unknown.
std::size_t sonarDtypeSize(std::uint32_t dtype);

struct ProjectedSonarImageMsg {
  RosHeader header;
  float frequency_hz = 0.0F;
  float sound_speed_mps = 0.0F;
  std::vector<float> tx_beamwidths_rad;
  std::vector<float> rx_beamwidths_rad;
  std::vector<Eigen::Vector3d> beam_directions;  ///< in the message's sonar frame
  std::vector<float> ranges_m;                   ///< centre of each range bin
  bool is_bigendian = false;
  std::uint32_t dtype = 0;
  std::uint32_t beam_count = 0;
  std::span<const std::uint8_t> data;  ///< points into the decoded bytes
};

/// A pose in a parent frame, from any of the vehicle pose messages.
struct RosPoseMsg {
  RosHeader header;            ///< frame_id: the world (parent) frame
  std::string child_frame_id;  ///< the body frame; empty for PoseStamped types
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

struct RosTransformMsg {
  RosHeader header;  ///< frame_id: the parent
  std::string child_frame_id;
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
};

/// sensor_msgs/msg/NavSatFix: header, NavSatStatus (int8 status, uint16 service), latitude,
/// longitude (degrees, WGS84), altitude (metres, positive up), float64[9] position_covariance,
/// uint8 position_covariance_type. Values are as sent: NaN and out-of-range ones are the
/// caller's to refuse.
struct NavSatFixMsg {
  RosHeader header;
  std::int8_t status = 0;     ///< NavSatStatus: -1 no fix, 0 fix, 1 SBAS, 2 GBAS
  std::uint16_t service = 1;  ///< NavSatStatus: 1 GPS, 2 GLONASS, 4 COMPASS, 8 GALILEO
  double latitude_deg = 0.0;
  double longitude_deg = 0.0;
  double altitude_m = 0.0;
};
inline constexpr std::int8_t kNavSatStatusNoFix = -1;

/// geographic_msgs/msg/GeoPoint (float64 latitude, longitude in WGS84 degrees, altitude in
/// metres, positive up), alone or as GeoPointStamped (std_msgs/Header header, GeoPoint
/// position). Values as sent.
struct GeoPointMsg {
  RosHeader header;  ///< zero for a GeoPoint
  double latitude_deg = 0.0;
  double longitude_deg = 0.0;
  double altitude_m = 0.0;
};

class CdrReader;
/// A std_msgs/Header at the reader's place (stamp checked: nanoseconds below 10^9).
RosHeader readRosHeader(CdrReader& in);
/// Only the header of any stamped message (cheap: for time stamps).
RosHeader decodeRosHeader(std::span<const std::uint8_t> cdr, const std::string& source,
                          const std::string& place);
ProjectedSonarImageMsg decodeProjectedSonarImage(std::span<const std::uint8_t> cdr,
                                                 const std::string& source,
                                                 const std::string& place);
/// The older acoustic_msgs/msg/SonarImage (std_msgs/Header header, float32 frequency,
/// sound_speed, azimuth_beamwidth, elevation_beamwidth, float32[] azimuth_angles,
/// elevation_angles, ranges, bool is_bigendian, uint8 data_size, uint8[] intensities) as a
/// ProjectedSonarImageMsg: beam directions (cos az, sin az, 0) in its NED sonar frame (X
/// forward, Y starboard: SonarAxes::Frd), tx_beamwidths {elevation_beamwidth}, data_size 1, 2
/// or 4 as uint8, uint16 or uint32; its data is azimuth-major (ImageLayout::BeamMajor).
ProjectedSonarImageMsg decodeLegacySonarImage(std::span<const std::uint8_t> cdr,
                                              const std::string& source, const std::string& place);
/// Either sonar image type, by `type`.
ProjectedSonarImageMsg decodeSonarImage(std::string_view type, std::span<const std::uint8_t> cdr,
                                        const std::string& source, const std::string& place);
/// Odometry, PoseStamped or PoseWithCovarianceStamped, by `type`.
RosPoseMsg decodeRosPose(std::string_view type, std::span<const std::uint8_t> cdr,
                         const std::string& source, const std::string& place);
NavSatFixMsg decodeNavSatFix(std::span<const std::uint8_t> cdr, const std::string& source,
                             const std::string& place);
std::vector<RosTransformMsg> decodeTfMessage(std::span<const std::uint8_t> cdr,
                                             const std::string& source, const std::string& place);
/// GeoPoint or GeoPointStamped, by `type`.
GeoPointMsg decodeGeoPoint(std::string_view type, std::span<const std::uint8_t> cdr,
                           const std::string& source, const std::string& place);

std::vector<std::uint8_t> encodeProjectedSonarImage(const ProjectedSonarImageMsg& msg);
/// An Odometry message (zero twist and covariances).
std::vector<std::uint8_t> encodeOdometry(const RosPoseMsg& msg);
/// A NavSatFix (covariance unknown: zeros, type 0).
std::vector<std::uint8_t> encodeNavSatFix(const NavSatFixMsg& msg);
std::vector<std::uint8_t> encodeTfMessage(const std::vector<RosTransformMsg>& transforms);
/// A GeoPointStamped.
std::vector<std::uint8_t> encodeGeoPointStamped(const GeoPointMsg& msg);

/// The message definition text of a type as ROS 2 writes it into MCAP schemas ("ros2msg":
/// the type's fields, then each dependency after a line of '=' and "MSG: pkg/Type").
std::string rosMessageDefinition(std::string_view type);

}  // namespace sonarcarve
