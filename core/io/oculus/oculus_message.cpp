#include "io/oculus/oculus_message.h"

#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "common/angles.h"
#include "common/error.h"
#include "io/files/yaml_fields.h"
#include "sonar/sonar_ranges.h"

namespace sonarcarve {
namespace {

static_assert(std::endian::native == std::endian::little,
              "the Oculus decoder reads little-endian fields in place");

// Byte offsets from the start of the message (header included), from the public Oculus.h
// (packed structures): OculusSimpleFireMessage and OculusSimplePingResult for versions 0/1,
// OculusSimpleFireMessage2 and OculusSimplePingResult2 for version 2.
struct PingLayout {
  std::size_t ping_id, status, frequency, temperature, pressure;
  std::size_t heading, pitch, roll;  // 0: not in this layout
  std::size_t speed_of_sound, ping_start_time, data_size, range_resolution, n_ranges, n_beams;
  std::size_t image_offset, image_size, size;
};
constexpr PingLayout kLayoutV1{
    53, 57, 61, 69, 77, 0, 0, 0, 85, 93, 97, 98, 106, 108, 110, 114, kOculusPingV1Size};
constexpr PingLayout kLayoutV2{
    89, 93, 97, 105, 113, 121, 129, 137, 145, 153, 161, 162, 170, 172, 190, 194, kOculusPingV2Size};
// The fire message, the same in both layouts up to the salinity.
constexpr std::size_t kMasterMode = 16, kGamma = 19, kFlags = 20, kRange = 21, kGain = 29,
                      kSpeedOfSound = 37, kSalinity = 45;

// Bounds-checked little-endian reads from a span.
class Bytes {
 public:
  Bytes(std::span<const std::uint8_t> bytes, const std::string& source)
      : bytes_(bytes), source_(source) {}

  template <typename T>
  T at(std::size_t offset, const char* field) const {
    if (offset > bytes_.size() || sizeof(T) > bytes_.size() - offset) {
      throw Error(source_, bytePlace(offset),
                  std::string("truncated: expected ") + field + " (" + std::to_string(sizeof(T)) +
                      " bytes), the data ends at byte " + std::to_string(bytes_.size()));
    }
    T value;
    std::memcpy(&value, bytes_.data() + offset, sizeof(T));
    return value;
  }
  [[noreturn]] void fail(std::size_t offset, const std::string& message) const {
    throw Error(source_, bytePlace(offset), message);
  }

 private:
  std::span<const std::uint8_t> bytes_;
  const std::string& source_;
};

std::string hex16(std::uint16_t value) {
  char text[8];
  std::snprintf(text, sizeof(text), "0x%04x", value);
  return text;
}

}  // namespace

OculusMessageHeader readOculusHeader(std::span<const std::uint8_t> bytes, std::size_t offset,
                                     const std::string& source) {
  const Bytes in(bytes, source);
  if (offset >= bytes.size()) {
    in.fail(offset, "expected an Oculus message header, found the end of the data");
  }
  if (bytes.size() - offset < kOculusHeaderSize) {
    in.fail(offset, "truncated Oculus message header: " + std::to_string(bytes.size() - offset) +
                        " of 16 bytes");
  }
  const auto id = in.at<std::uint16_t>(offset, "oculusId");
  if (id != kOculusId) {
    in.fail(offset, "not an Oculus message: oculusId is " + hex16(id) + ", expected 0x4f53");
  }
  OculusMessageHeader h;
  h.offset = offset;
  h.src_device = in.at<std::uint16_t>(offset + 2, "srcDeviceId");
  h.dst_device = in.at<std::uint16_t>(offset + 4, "dstDeviceId");
  h.msg_id = in.at<std::uint16_t>(offset + 6, "msgId");
  h.msg_version = in.at<std::uint16_t>(offset + 8, "msgVersion");
  h.payload_size = in.at<std::uint32_t>(offset + 10, "payloadSize");
  const std::size_t available = bytes.size() - offset - kOculusHeaderSize;
  if (h.payload_size > available) {
    in.fail(offset + 10, "truncated message: payloadSize " + std::to_string(h.payload_size) +
                             " runs past the end of the data (" + std::to_string(available) +
                             " bytes after the header)");
  }
  return h;
}

OculusPing decodeOculusPing(std::span<const std::uint8_t> bytes, std::size_t offset,
                            const std::string& source, bool with_image) {
  const Bytes in(bytes, source);
  OculusPing p;
  p.header = readOculusHeader(bytes, offset, source);
  const OculusMessageHeader& h = p.header;
  if (h.msg_id != kOculusSimplePingResult) {
    in.fail(offset + 6, "message id " + std::to_string(h.msg_id) +
                            " is not a simple ping result (expected 35)");
  }
  if (h.msg_version > 2) {
    in.fail(offset + 8, "unknown simple ping result version " + std::to_string(h.msg_version) +
                            " (expected 0, 1 or 2)");
  }
  const PingLayout& layout = h.msg_version == 2 ? kLayoutV2 : kLayoutV1;
  const std::size_t message_size = h.size();
  if (message_size < layout.size) {
    in.fail(offset + 10, "payloadSize " + std::to_string(h.payload_size) +
                             " is too small for a version " + std::to_string(h.msg_version) +
                             " ping result (expected at least " +
                             std::to_string(layout.size - kOculusHeaderSize) + ")");
  }
  // From here every fixed field lies inside the message.
  const auto field = [&](std::size_t at) { return offset + at; };
  p.master_mode = in.at<std::uint8_t>(field(kMasterMode), "masterMode");
  p.gamma = in.at<std::uint8_t>(field(kGamma), "gammaCorrection");
  p.flags = in.at<std::uint8_t>(field(kFlags), "flags");
  p.range_demand = in.at<double>(field(kRange), "range");
  p.gain_percent = in.at<double>(field(kGain), "gainPercent");
  p.speed_of_sound_demand_mps = in.at<double>(field(kSpeedOfSound), "speedOfSound");
  p.salinity_ppt = in.at<double>(field(kSalinity), "salinity");
  p.ping_id = in.at<std::uint32_t>(field(layout.ping_id), "pingId");
  p.status = in.at<std::uint32_t>(field(layout.status), "status");
  p.frequency_hz = in.at<double>(field(layout.frequency), "frequency");
  p.temperature_c = in.at<double>(field(layout.temperature), "temperature");
  p.pressure_bar = in.at<double>(field(layout.pressure), "pressure");
  if (layout.heading != 0) {
    p.heading_deg = in.at<double>(field(layout.heading), "heading");
    p.pitch_deg = in.at<double>(field(layout.pitch), "pitch");
    p.roll_deg = in.at<double>(field(layout.roll), "roll");
    p.ping_start_time = in.at<double>(field(layout.ping_start_time), "pingStartTime");
  } else {
    p.ping_start_time = in.at<std::uint32_t>(field(layout.ping_start_time), "pingStartTime");
  }
  p.speed_of_sound_mps = in.at<double>(field(layout.speed_of_sound), "speedOfSoundUsed");
  const auto data_size = in.at<std::uint8_t>(field(layout.data_size), "dataSize");
  p.range_resolution_m = in.at<double>(field(layout.range_resolution), "rangeResolution");
  p.n_ranges = in.at<std::uint16_t>(field(layout.n_ranges), "nRanges");
  p.n_beams = in.at<std::uint16_t>(field(layout.n_beams), "nBeams");
  p.image_offset = in.at<std::uint32_t>(field(layout.image_offset), "imageOffset");
  p.image_size = in.at<std::uint32_t>(field(layout.image_size), "imageSize");

  if (data_size > 1) {
    in.fail(field(layout.data_size), "dataSize " + std::to_string(data_size) +
                                         ": only 8-bit (0) and 16-bit (1) samples are supported");
  }
  p.sample_bytes = data_size == 0 ? 1 : 2;
  if (const auto problem = outsideRange(p.speed_of_sound_mps, kSoundSpeed)) {
    in.fail(field(layout.speed_of_sound), "speedOfSoundUsed: " + *problem);
  }
  if (p.n_ranges == 0) {
    in.fail(field(layout.n_ranges), "nRanges is 0: expected at least one range line");
  }
  if (p.n_beams == 0 || p.n_beams > kOculusMaxBeams) {
    in.fail(field(layout.n_beams), "nBeams " + std::to_string(p.n_beams) + ": expected 1 to " +
                                       std::to_string(kOculusMaxBeams));
  }

  // The bearing table follows the fixed part and must end before the image.
  const std::size_t table_start = layout.size;
  const std::size_t table_end = table_start + 2 * static_cast<std::size_t>(p.n_beams);
  if (table_end > message_size) {
    in.fail(field(table_start), "truncated bearing table: " + std::to_string(p.n_beams) +
                                    " beams need " + std::to_string(table_end - table_start) +
                                    " bytes, the message ends at byte " +
                                    std::to_string(offset + message_size));
  }
  p.bearings_rad.resize(static_cast<std::size_t>(p.n_beams));
  int previous = 0;
  for (int j = 0; j < p.n_beams; ++j) {
    const std::size_t at = field(table_start + 2 * static_cast<std::size_t>(j));
    const int centi_deg = in.at<std::int16_t>(at, "bearing");
    if (centi_deg <= -18000 || centi_deg >= 18000) {
      in.fail(at, "bearing " + std::to_string(j) + " is " + shortestNumber(centi_deg * 0.01) +
                      " deg: expected within (-180, 180)");
    }
    if (j > 0 && centi_deg <= previous) {
      in.fail(at, "bearing table does not increase: beam " + std::to_string(j) + " at " +
                      shortestNumber(centi_deg * 0.01) + " deg after " +
                      shortestNumber(previous * 0.01) + " deg");
    }
    previous = centi_deg;
    p.bearings_rad[static_cast<std::size_t>(j)] = degToRad(centi_deg * 0.01);
  }
  // The sonar's geometry against the ranges a mission.yaml is held to (sonar/sonar_ranges.h).
  const RecordedGeometry geometry{
      .near_range_m = {"", 0.0},  // the first range line starts at the transducer
      .range_resolution_m = {"rangeResolution", p.range_resolution_m},
      .bins = p.n_ranges,
      .field_of_view_deg = {"bearing table (its span)",
                            radToDeg(p.bearings_rad.back() - p.bearings_rad.front())},
      .vertical_aperture_deg = {}};  // not in the message: given or assumed by the reader
  if (const auto problem = recordedGeometryProblem(geometry)) {
    const bool range = problem->rfind("rangeResolution", 0) == 0;
    in.fail(field(range ? layout.range_resolution : table_start), *problem);
  }

  // Image: rows of nBeams samples, each row with a 4-byte gain before it or not. The sizes
  // decide (the gain flag of version 2 messages is not reliable, see docs/formats.md).
  const std::size_t rows = static_cast<std::size_t>(p.n_ranges);
  const std::size_t row_samples = static_cast<std::size_t>(p.n_beams) * p.sample_bytes;
  if (p.image_size == rows * row_samples) {
    p.has_gain = false;
  } else if (p.image_size == rows * (row_samples + 4)) {
    p.has_gain = true;
  } else {
    in.fail(field(layout.image_size),
            "imageSize " + std::to_string(p.image_size) + " does not match nRanges x nBeams x " +
                std::to_string(p.sample_bytes) + " bytes = " + std::to_string(rows * row_samples) +
                " (or " + std::to_string(rows * (row_samples + 4)) + " with a gain per row)");
  }
  if (p.image_offset < table_end) {
    in.fail(field(layout.image_offset), "imageOffset " + std::to_string(p.image_offset) +
                                            " overlaps the header or the bearing table (which "
                                            "ends at " +
                                            std::to_string(table_end) + ")");
  }
  if (static_cast<std::size_t>(p.image_offset) + p.image_size > message_size) {
    in.fail(field(layout.image_offset), "image (imageOffset " + std::to_string(p.image_offset) +
                                            " + imageSize " + std::to_string(p.image_size) +
                                            ") runs past the end of the message (" +
                                            std::to_string(message_size) + " bytes)");
  }
  if (!with_image) {
    return p;
  }

  const std::size_t stride = row_samples + (p.has_gain ? 4 : 0);
  const std::uint8_t* image = bytes.data() + offset + p.image_offset;
  p.image.create(p.n_ranges, p.n_beams, CV_32F);
  if (p.has_gain) {
    p.row_gain.resize(rows);
  }
  for (std::size_t r = 0; r < rows; ++r) {
    const std::uint8_t* row = image + r * stride;
    if (p.has_gain) {
      std::memcpy(&p.row_gain[r], row, 4);
      row += 4;
    }
    float* out = p.image.ptr<float>(static_cast<int>(r));
    for (int c = 0; c < p.n_beams; ++c) {
      if (p.sample_bytes == 1) {
        out[c] = row[c];
      } else {
        std::uint16_t v;
        std::memcpy(&v, row + 2 * c, 2);
        out[c] = v;
      }
    }
  }
  return p;
}

}  // namespace sonarcarve
