// Blueprint Subsea Oculus network messages (docs/formats.md, "Oculus messages"): a 16-byte
// little-endian header (oculusId 0x4f53, source and destination device, msgId, msgVersion,
// payloadSize, spare) followed by payloadSize bytes. The simple ping result (msgId 0x23)
// carries one polar image in one of two layouts: msgVersion 0 and 1 ("SimplePingResult",
// 122 bytes before the bearing table) or 2 ("SimplePingResult2", 202 bytes). The bearing
// table (nBeams x i16, 0.01 degree) follows the fixed part; the image lies at imageOffset from
// the start of the message: nRanges rows (near to far) of nBeams 8- or 16-bit samples, each
// row optionally preceded by a 4-byte gain.
//
// The decoder works on a byte span with the message at `offset`, so that errors name the byte
// of the file where the problem is. Every check throws sonarcarve::Error(source, "byte N",
// what was expected); nothing is read outside the span.
#pragma once

#include <cstddef>
#include <cstdint>
#include <opencv2/core.hpp>
#include <span>
#include <string>
#include <vector>

namespace sonarcarve {

inline constexpr std::uint16_t kOculusId = 0x4f53;
inline constexpr std::size_t kOculusHeaderSize = 16;
inline constexpr std::uint16_t kOculusSimplePingResult = 0x23;
/// Fixed part of the simple ping result, header included: version 0/1 and version 2 layouts.
inline constexpr std::size_t kOculusPingV1Size = 122;
inline constexpr std::size_t kOculusPingV2Size = 202;
/// Beams above this are treated as a corrupt count (Oculus sonars form 256 or 512 beams).
inline constexpr int kOculusMaxBeams = 2048;

struct OculusMessageHeader {
  std::size_t offset = 0;  ///< byte of the span where the message starts
  std::uint16_t src_device = 0;
  std::uint16_t dst_device = 0;
  std::uint16_t msg_id = 0;
  std::uint16_t msg_version = 0;
  std::uint32_t payload_size = 0;
  /// Header plus payload.
  std::size_t size() const { return kOculusHeaderSize + payload_size; }
};

/// One decoded simple ping result. Values are as the sonar sent them, in SI units.
struct OculusPing {
  OculusMessageHeader header;
  // The fire message (the settings the ping was made with).
  std::uint8_t master_mode = 0;  ///< 1 = low frequency (wide), 2 = high frequency (narrow)
  std::uint8_t gamma = 0;     ///< the samples' gamma in 255ths; 0 and 255: 1 (linear), 127: 0.498
  std::uint8_t flags = 0;     ///< bit 0 range in metres, bit 1 16-bit, bit 2 gain sent
  double range_demand = 0.0;  ///< metres or percent, as flags bit 0 says
  double gain_percent = 0.0;
  double speed_of_sound_demand_mps = 0.0;  ///< 0: the sonar computes it from salinity
  double salinity_ppt = 0.0;
  // The ping result.
  std::uint32_t ping_id = 0;
  std::uint32_t status = 0;
  double frequency_hz = 0.0;
  double temperature_c = 0.0;
  double pressure_bar = 0.0;
  double heading_deg = 0.0;  ///< version 2 only (0 otherwise)
  double pitch_deg = 0.0;    ///< version 2 only
  double roll_deg = 0.0;     ///< version 2 only
  double speed_of_sound_mps = 0.0;
  /// Version 2: seconds since the sonar powered up. Version 0/1: the raw u32 (unit not
  /// documented publicly; see docs/formats.md for how the importer reads it).
  double ping_start_time = 0.0;
  int sample_bytes = 1;  ///< 1 or 2
  bool has_gain = false;
  double range_resolution_m = 0.0;
  int n_ranges = 0;
  int n_beams = 0;
  std::uint32_t image_offset = 0;
  std::uint32_t image_size = 0;
  std::vector<double> bearings_rad;     ///< the sonar's own table, port to starboard
  std::vector<std::uint32_t> row_gain;  ///< per-row gain as sent (empty without gain)
  cv::Mat image;  ///< CV_32F, n_ranges x n_beams, counts as sent (empty if not decoded)
};

/// Reads the header of the message at `offset`. Throws Error if it is cut off, the oculusId
/// is not 0x4f53, or the payload runs past the end of `bytes`.
OculusMessageHeader readOculusHeader(std::span<const std::uint8_t> bytes, std::size_t offset,
                                     const std::string& source);

/// Decodes the simple ping result at `offset` (header included). Without `with_image` the
/// image is checked for size but not converted. Throws Error naming `source` and the byte on
/// any inconsistency: another message id, an unknown version, sizes that do not agree, zero or
/// absurd counts, a bearing table that does not increase, a non-positive range resolution.
OculusPing decodeOculusPing(std::span<const std::uint8_t> bytes, std::size_t offset,
                            const std::string& source, bool with_image = true);

}  // namespace sonarcarve
