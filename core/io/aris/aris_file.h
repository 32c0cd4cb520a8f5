// ARIS recordings (.aris, Sound Metrics): a 1024-byte file header, then frames, each a
// 1024-byte frame header followed by beams x samples unsigned bytes (0..255 = 0..80 dB).
// Layout and field offsets from the public ARIS file SDK (SoundMetrics/aris-file-sdk:
// type-definitions/C/FileHeader.h, FrameHeader.h, docs/understanding-aris-data.md); this is
// our own reader. All fields are little-endian.
//
// Geometry: the window starts at SampleStartDelay * SoundSpeed / 2 and each sample covers
// SamplePeriod * SoundSpeed / 2; the beam count follows from PingMode. Samples are stored
// sample-major (all beams of sample 0, then of sample 1, ...) and ARIS beam 0 is the
// right-most (starboard) beam, so our image column c (port to starboard) is ARIS beam
// beams - 1 - c. Only files whose samples are already reordered (ReorderedSamples != 0, all
// recordings written by Sound Metrics' tools) are read.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace sonarcarve {

inline constexpr std::uint32_t kArisFileVersion = 0x05464444;  ///< "DDF" + 0x05
inline constexpr std::size_t kArisFileHeaderSize = 1024;
inline constexpr std::size_t kArisFrameHeaderSize = 1024;

/// What a frame header says (the fields we use).
struct ArisFrameInfo {
  std::uint32_t frame_index = 0;
  std::uint64_t time_us = 0;  ///< FrameTime, microseconds since 1970
  std::uint32_t ping_mode = 0;
  std::uint32_t beams = 0;  ///< from the ping mode
  std::uint32_t samples_per_beam = 0;
  std::uint32_t sample_period_us = 0;
  std::uint32_t sample_start_delay_us = 0;
  float sound_speed_mps = 0.0F;
  bool large_lens = false;  ///< telephoto lens
  bool reordered = false;
  float depth_m = 0.0F;  ///< vehicle fields (zero when the recorder had none)
  float pitch_deg = 0.0F;
  float roll_deg = 0.0F;
  float heading_deg = 0.0F;

  double windowStart() const { return sample_start_delay_us * 1e-6 * sound_speed_mps / 2.0; }
  double sampleLength() const { return sample_period_us * 1e-6 * sound_speed_mps / 2.0; }
  double windowEnd() const { return windowStart() + sampleLength() * samples_per_beam; }
};

/// The beam count of an ARIS ping mode (1-2: 48; 3-5: 96; 6-8: 64; 9-12: 128), 0 if
/// unknown.
std::uint32_t arisBeamsOfPingMode(std::uint32_t ping_mode);

/// True if the file starts with the ARIS version magic. Never throws.
bool looksLikeArisFile(const std::filesystem::path& path);

class ArisFile {
 public:
  /// Reads and checks the file header and every frame header; the geometry of frame 0 is the
  /// recording's. Throws Error (file, byte, what was expected) for an empty or truncated file,
  /// a wrong magic or an absurd first frame; later frames that disagree or are cut short are
  /// left out and listed in problems().
  static ArisFile open(const std::filesystem::path& path);

  const std::filesystem::path& path() const { return path_; }
  const std::vector<ArisFrameInfo>& frames() const { return frames_; }
  const std::vector<std::string>& problems() const { return problems_; }
  /// Frame `k`'s samples as an image: rows = samples (near to far), cols = beams (port to
  /// starboard), CV_32F counts 0..255. Throws Error naming the file and the frame.
  cv::Mat image(std::size_t k) const;

 private:
  std::filesystem::path path_;
  std::vector<ArisFrameInfo> frames_;
  std::vector<std::uint64_t> offsets_;  ///< of each kept frame's header
  std::vector<std::string> problems_;
};

}  // namespace sonarcarve
