// A test-only encoder of Oculus messages and Oculus ViewPoint recordings. It writes the fields
// one after another in the order the public Oculus.h declares them (packed structures), so it
// checks the decoder's offset tables independently. Only for building test inputs.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace sonarcarve::test {

/// The real ping of tests/data/oculus (README.md there lists its values).
std::filesystem::path oculusFixture();

struct OculusPingSpec {
  std::uint16_t version = 0;  ///< 0 or 1: SimplePingResult; 2: SimplePingResult2
  std::uint16_t msg_id = 0x23;
  int n_beams = 16;
  int n_ranges = 10;
  bool sixteen_bit = false;
  bool gain = false;
  std::uint8_t gamma = 0;  ///< the fire message's gammaCorrection (0: linear)
  double range_resolution_m = 0.01;
  double frequency_hz = 2.1e6;
  double speed_of_sound_mps = 1500.0;
  std::uint32_t ping_id = 1;
  double ping_start_time = 0.0;                               ///< v2: seconds; v0/1: stored as u32
  double heading_deg = 0.0, pitch_deg = 0.0, roll_deg = 0.0;  ///< v2 only
  std::vector<std::int16_t> bearings_centideg;  ///< default: -45 .. +45 deg, finer at centre
  std::uint32_t image_offset = 0;  ///< 0: right after the bearing table, rounded up to 8
};

/// The sample the encoder stores at (row, col): distinct values so mistakes show.
std::uint16_t oculusSample(const OculusPingSpec& spec, int row, int col);
/// The gain the encoder stores before row `row` (with spec.gain).
std::uint32_t oculusRowGain(int row);
/// The default bearing table of `n_beams` beams, 0.01 deg.
std::vector<std::int16_t> oculusBearings(int n_beams);

/// One complete simple ping result message (header + payload).
std::vector<std::uint8_t> encodeOculusPing(const OculusPingSpec& spec);
/// Any message: header + `payload`.
std::vector<std::uint8_t> encodeOculusMessage(std::uint16_t msg_id, std::uint16_t version,
                                              const std::vector<std::uint8_t>& payload);

struct RecordingItem {
  std::uint16_t type = 10;  ///< 10: Oculus sonar data
  double time_s = 0.0;
  std::vector<std::uint8_t> payload;
  bool compress = false;  ///< qCompress the payload (4-byte big-endian size + zlib)
};
/// An Oculus ViewPoint log v1 (.oculus): file header and items.
std::vector<std::uint8_t> encodeRecording(const std::vector<RecordingItem>& items);

std::vector<std::uint8_t> concat(const std::vector<std::vector<std::uint8_t>>& parts);
void writeBytes(const std::string& path, const std::vector<std::uint8_t>& bytes);
std::vector<std::uint8_t> readBytes(const std::string& path);

}  // namespace sonarcarve::test
