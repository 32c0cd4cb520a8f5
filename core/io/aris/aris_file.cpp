#include "io/aris/aris_file.h"

#include <array>
#include <cstring>
#include <fstream>

#include "common/error.h"
#include "io/files/input_file.h"
#include "sonar/sonar_ranges.h"

namespace sonarcarve {
namespace {

// Frame header field offsets (FrameHeader.h of the ARIS file SDK).
constexpr std::size_t kFrameIndexAt = 0;
constexpr std::size_t kFrameTimeAt = 4;
constexpr std::size_t kDepthAt = 128;
constexpr std::size_t kPitchAt = 136;
constexpr std::size_t kRollAt = 144;
constexpr std::size_t kHeadingAt = 152;
constexpr std::size_t kPingModeAt = 436;
constexpr std::size_t kSamplePeriodAt = 452;
constexpr std::size_t kSoundSpeedAt = 464;
constexpr std::size_t kSamplesPerBeamAt = 468;
constexpr std::size_t kSampleStartDelayAt = 476;
constexpr std::size_t kLargeLensAt = 480;
constexpr std::size_t kReorderedSamplesAt = 516;

// Bounds far beyond any ARIS (4096 samples per beam is the largest setting).
constexpr std::uint32_t kMaxSamplesPerBeam = 65536;

using Header = std::array<unsigned char, kArisFrameHeaderSize>;

template <typename T>
T field(const Header& header, std::size_t at) {
  T value{};
  std::memcpy(&value, header.data() + at, sizeof(T));
  return value;
}

ArisFrameInfo decodeFrameHeader(const Header& h) {
  ArisFrameInfo info;
  info.frame_index = field<std::uint32_t>(h, kFrameIndexAt);
  info.time_us = field<std::uint64_t>(h, kFrameTimeAt);
  info.ping_mode = field<std::uint32_t>(h, kPingModeAt);
  info.beams = arisBeamsOfPingMode(info.ping_mode);
  info.samples_per_beam = field<std::uint32_t>(h, kSamplesPerBeamAt);
  info.sample_period_us = field<std::uint32_t>(h, kSamplePeriodAt);
  info.sample_start_delay_us = field<std::uint32_t>(h, kSampleStartDelayAt);
  info.sound_speed_mps = field<float>(h, kSoundSpeedAt);
  info.large_lens = field<std::uint32_t>(h, kLargeLensAt) != 0;
  info.reordered = field<std::uint32_t>(h, kReorderedSamplesAt) != 0;
  info.depth_m = field<float>(h, kDepthAt);
  info.pitch_deg = field<float>(h, kPitchAt);
  info.roll_deg = field<float>(h, kRollAt);
  info.heading_deg = field<float>(h, kHeadingAt);
  return info;
}

// What is wrong with a frame header's geometry, or "" if it is usable.
std::string geometryProblem(const ArisFrameInfo& info) {
  if (info.beams == 0) {
    return "PingMode " + std::to_string(info.ping_mode) + " (expected 1 to 12)";
  }
  if (info.samples_per_beam == 0 || info.samples_per_beam > kMaxSamplesPerBeam) {
    return "SamplesPerBeam " + std::to_string(info.samples_per_beam) + " (expected 1 to " +
           std::to_string(kMaxSamplesPerBeam) + ")";
  }
  if (info.sample_period_us == 0) {
    return "SamplePeriod 0 (expected a positive number of microseconds)";
  }
  if (const auto problem = outsideRange(info.sound_speed_mps, kSoundSpeed)) {
    return "SoundSpeed: " + *problem;
  }
  // The range window against the ranges a mission.yaml is held to (sonar/sonar_ranges.h); the
  // bearings and the aperture are the lens's, not the file's.
  const RecordedGeometry geometry{
      .near_range_m = {"SampleStartDelay (the window's start)", info.windowStart()},
      .range_resolution_m = {"SamplePeriod (a sample's length)", info.sampleLength()},
      .bins = static_cast<int>(info.samples_per_beam),
      .field_of_view_deg = {},
      .vertical_aperture_deg = {}};
  if (const auto problem = recordedGeometryProblem(geometry)) {
    return *problem;
  }
  if (!info.reordered) {
    return "ReorderedSamples 0 (samples in the sonar's raw order; expected a recording)";
  }
  return "";
}

bool sameGeometry(const ArisFrameInfo& a, const ArisFrameInfo& b) {
  return a.beams == b.beams && a.samples_per_beam == b.samples_per_beam &&
         a.sample_period_us == b.sample_period_us &&
         a.sample_start_delay_us == b.sample_start_delay_us && a.large_lens == b.large_lens;
}

std::ifstream openStream(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw Error(path.string(), "", "cannot open file (missing or unreadable)");
  }
  return in;
}

bool readAt(std::ifstream& in, std::uint64_t offset, void* out, std::size_t size) {
  in.clear();
  in.seekg(static_cast<std::streamoff>(offset));
  in.read(static_cast<char*>(out), static_cast<std::streamsize>(size));
  return static_cast<std::size_t>(in.gcount()) == size;
}

}  // namespace

std::uint32_t arisBeamsOfPingMode(std::uint32_t ping_mode) {
  if (ping_mode >= 1 && ping_mode <= 2)
    return 48;
  if (ping_mode >= 3 && ping_mode <= 5)
    return 96;
  if (ping_mode >= 6 && ping_mode <= 8)
    return 64;
  if (ping_mode >= 9 && ping_mode <= 12)
    return 128;
  return 0;
}

bool looksLikeArisFile(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  std::uint32_t version = 0;
  return in && readAt(in, 0, &version, sizeof version) && version == kArisFileVersion;
}

ArisFile ArisFile::open(const std::filesystem::path& path) {
  requireRegularFile(path, "ARIS recording");
  const std::string source = path.string();
  std::ifstream in = openStream(path);
  const std::uint64_t file_size = std::filesystem::file_size(path);
  std::uint32_t version = 0;
  if (file_size < kArisFileHeaderSize || !readAt(in, 0, &version, sizeof version)) {
    throw Error(source, bytePlace(0),
                "file of " + std::to_string(file_size) +
                    " bytes is shorter than the 1024-byte ARIS file header");
  }
  if (version != kArisFileVersion) {
    throw Error(source, bytePlace(0), "not an ARIS recording (expected version 0x05464444)");
  }
  ArisFile file;
  file.path_ = path;
  Header header{};
  std::uint64_t offset = kArisFileHeaderSize;
  while (offset < file_size) {
    const std::string place = "frame " + std::to_string(file.frames_.size()) + ", " +
                              bytePlace(static_cast<std::size_t>(offset));
    if (!readAt(in, offset, header.data(), header.size())) {
      file.problems_.push_back(source + ": " + place + ": truncated frame header (" +
                               std::to_string(file_size - offset) + " of 1024 bytes)");
      break;
    }
    const ArisFrameInfo info = decodeFrameHeader(header);
    std::string problem = geometryProblem(info);
    if (problem.empty() && !file.frames_.empty() && !sameGeometry(info, file.frames_.front())) {
      problem = "geometry differs from frame 0 (beams, samples, window or lens)";
    }
    if (!problem.empty() && file.frames_.empty()) {
      throw Error(source, place, problem);
    }
    if (!problem.empty()) {
      // Without a trustworthy size the following frames cannot be found: stop here.
      file.problems_.push_back(source + ": " + place + ": " + problem + "; reading stopped");
      break;
    }
    const std::uint64_t data_size = static_cast<std::uint64_t>(info.beams) * info.samples_per_beam;
    const std::uint64_t end = offset + kArisFrameHeaderSize + data_size;
    if (end > file_size) {
      file.problems_.push_back(source + ": " + place + ": truncated samples (" +
                               std::to_string(file_size - offset - kArisFrameHeaderSize) + " of " +
                               std::to_string(data_size) + " bytes)");
      break;
    }
    file.frames_.push_back(info);
    file.offsets_.push_back(offset);
    offset = end;
  }
  if (file.frames_.empty()) {
    throw Error(source, bytePlace(kArisFileHeaderSize),
                "no complete frame (expected a 1024-byte frame header and its samples)" +
                    (file.problems_.empty() ? std::string() : ": " + file.problems_.front()));
  }
  return file;
}

cv::Mat ArisFile::image(std::size_t k) const {
  const ArisFrameInfo& info = frames_.at(k);
  const int beams = static_cast<int>(info.beams);
  const int samples = static_cast<int>(info.samples_per_beam);
  std::vector<unsigned char> raw(static_cast<std::size_t>(beams) * info.samples_per_beam);
  std::ifstream in = openStream(path_);
  if (!readAt(in, offsets_[k] + kArisFrameHeaderSize, raw.data(), raw.size())) {
    throw Error(path_.string(), "frame " + std::to_string(k), "samples could not be read");
  }
  cv::Mat image(samples, beams, CV_32F);
  for (int row = 0; row < samples; ++row) {
    const unsigned char* sample = raw.data() + static_cast<std::size_t>(row) * beams;
    auto* out = image.ptr<float>(row);
    for (int col = 0; col < beams; ++col) {
      out[col] = static_cast<float>(sample[beams - 1 - col]);  // ARIS beam 0 is starboard
    }
  }
  return image;
}

}  // namespace sonarcarve
