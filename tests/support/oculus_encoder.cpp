#include "support/oculus_encoder.h"

#include <zlib.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace sonarcarve::test {
namespace {

class Writer {
 public:
  template <typename T>
  void put(T value) {
    const auto* p = reinterpret_cast<const std::uint8_t*>(&value);
    bytes.insert(bytes.end(), p, p + sizeof(T));
  }
  void pad(std::size_t n) { bytes.insert(bytes.end(), n, 0); }
  std::vector<std::uint8_t> bytes;
};

void putHeader(Writer& w, std::uint16_t msg_id, std::uint16_t version, std::uint32_t payload) {
  w.put<std::uint16_t>(0x4f53);  // oculusId
  w.put<std::uint16_t>(7892);    // srcDeviceId
  w.put<std::uint16_t>(0);       // dstDeviceId
  w.put<std::uint16_t>(msg_id);
  w.put<std::uint16_t>(version);
  w.put<std::uint32_t>(payload);
  w.put<std::uint16_t>(0);  // spare2
}

}  // namespace

std::filesystem::path oculusFixture() {
  return std::filesystem::path(SONARCARVE_TEST_DATA_DIR) / "oculus" / "one_ping_8bit.raw";
}

std::uint16_t oculusSample(const OculusPingSpec& spec, int row, int col) {
  const int v = row * 31 + col * 7 + 3;
  return static_cast<std::uint16_t>(spec.sixteen_bit ? (v * 257) % 65536 : v % 256);
}

std::uint32_t oculusRowGain(int row) {
  return 1000u + 17u * static_cast<std::uint32_t>(row);
}

std::vector<std::int16_t> oculusBearings(int n_beams) {
  std::vector<std::int16_t> table;
  for (int j = 0; j < n_beams; ++j) {
    const double u = -1.0 + 2.0 * (j + 0.5) / n_beams;
    table.push_back(static_cast<std::int16_t>(
        std::lround(100.0 * std::asin(u * std::sin(0.25 * M_PI)) * 180.0 / M_PI)));
  }
  return table;
}

std::vector<std::uint8_t> encodeOculusMessage(std::uint16_t msg_id, std::uint16_t version,
                                              const std::vector<std::uint8_t>& payload) {
  Writer w;
  putHeader(w, msg_id, version, static_cast<std::uint32_t>(payload.size()));
  w.bytes.insert(w.bytes.end(), payload.begin(), payload.end());
  return w.bytes;
}

std::vector<std::uint8_t> encodeOculusPing(const OculusPingSpec& s) {
  const std::vector<std::int16_t> bearings =
      s.bearings_centideg.empty() ? oculusBearings(s.n_beams) : s.bearings_centideg;
  const bool v2 = s.version == 2;
  const std::size_t fixed = v2 ? 202 : 122;
  const std::size_t table_end = fixed + 2 * bearings.size();
  const std::uint32_t image_offset =
      s.image_offset != 0 ? s.image_offset : static_cast<std::uint32_t>((table_end + 7) / 8 * 8);
  const int sample_bytes = s.sixteen_bit ? 2 : 1;
  const std::uint32_t row_bytes =
      static_cast<std::uint32_t>(s.n_beams * sample_bytes) + (s.gain ? 4u : 0u);
  const std::uint32_t image_size = row_bytes * static_cast<std::uint32_t>(s.n_ranges);
  const std::uint32_t message_size = image_offset + image_size;

  Writer w;
  putHeader(w, s.msg_id, s.version, message_size - 16);
  // OculusSimpleFireMessage(2)
  w.put<std::uint8_t>(2);        // masterMode: high frequency
  w.put<std::uint8_t>(0);        // pingRate
  w.put<std::uint8_t>(0);        // networkSpeed
  w.put<std::uint8_t>(s.gamma);  // gammaCorrection
  w.put<std::uint8_t>(
      static_cast<std::uint8_t>(0x09 | (s.sixteen_bit ? 0x02 : 0) | (s.gain ? 0x04 : 0)));  // flags
  w.put<double>(5.0);                                                                       // range
  w.put<double>(60.0);  // gainPercent
  w.put<double>(0.0);   // speedOfSound
  w.put<double>(35.0);  // salinity
  if (v2) {
    w.put<std::uint32_t>(0);  // extFlags
    w.pad(8 * 4);             // reserved[8]
  }
  // OculusSimplePingResult(2)
  w.put<std::uint32_t>(s.ping_id);
  w.put<std::uint32_t>(0);  // status
  w.put<double>(s.frequency_hz);
  w.put<double>(12.5);  // temperature
  w.put<double>(3.25);  // pressure
  if (v2) {
    w.put<double>(s.heading_deg);
    w.put<double>(s.pitch_deg);
    w.put<double>(s.roll_deg);
  }
  w.put<double>(s.speed_of_sound_mps);
  if (v2) {
    w.put<double>(s.ping_start_time);
  } else {
    w.put<std::uint32_t>(static_cast<std::uint32_t>(s.ping_start_time));
  }
  w.put<std::uint8_t>(s.sixteen_bit ? 1 : 0);  // dataSize
  w.put<double>(s.range_resolution_m);
  w.put<std::uint16_t>(static_cast<std::uint16_t>(s.n_ranges));
  w.put<std::uint16_t>(static_cast<std::uint16_t>(s.n_beams));
  if (v2) {
    w.pad(4 * 4);  // spare0..3
  }
  w.put<std::uint32_t>(image_offset);
  w.put<std::uint32_t>(image_size);
  w.put<std::uint32_t>(message_size);
  if (w.bytes.size() != fixed) {
    throw std::logic_error("encoder: fixed part is " + std::to_string(w.bytes.size()));
  }
  for (std::int16_t b : bearings) {
    w.put<std::int16_t>(b);
  }
  w.pad(image_offset - w.bytes.size());
  for (int r = 0; r < s.n_ranges; ++r) {
    if (s.gain) {
      w.put<std::uint32_t>(oculusRowGain(r));
    }
    for (int c = 0; c < s.n_beams; ++c) {
      if (s.sixteen_bit) {
        w.put<std::uint16_t>(oculusSample(s, r, c));
      } else {
        w.put<std::uint8_t>(static_cast<std::uint8_t>(oculusSample(s, r, c)));
      }
    }
  }
  return w.bytes;
}

std::vector<std::uint8_t> encodeRecording(const std::vector<RecordingItem>& items) {
  Writer w;
  // RmLogHeader: naturally aligned, 48 bytes.
  w.put<std::uint32_t>(0x11223344);
  w.put<std::uint32_t>(48);
  char source[16] = "Oculus";
  for (char c : source) {
    w.put<char>(c);
  }
  w.put<std::uint16_t>(1);  // version
  w.put<std::uint16_t>(0);  // encryption
  w.pad(4);
  w.put<std::int64_t>(0);       // key
  w.put<double>(1700000000.0);  // time
  for (const RecordingItem& item : items) {
    std::vector<std::uint8_t> payload = item.payload;
    if (item.compress) {
      uLongf size = compressBound(static_cast<uLong>(payload.size()));
      std::vector<std::uint8_t> z(size);
      compress(z.data(), &size, payload.data(), static_cast<uLong>(payload.size()));
      z.resize(size);
      const auto n = static_cast<std::uint32_t>(payload.size());
      payload = {static_cast<std::uint8_t>(n >> 24), static_cast<std::uint8_t>(n >> 16),
                 static_cast<std::uint8_t>(n >> 8), static_cast<std::uint8_t>(n)};
      payload.insert(payload.end(), z.begin(), z.end());
    }
    // RmLogItem: naturally aligned, 40 bytes.
    w.put<std::uint32_t>(0xaabbccdd);
    w.put<std::uint32_t>(40);
    w.put<std::uint16_t>(item.type);
    w.put<std::uint16_t>(0);  // version
    w.pad(4);
    w.put<double>(item.time_s);
    w.put<std::uint16_t>(item.compress ? 1 : 0);
    w.pad(2);
    w.put<std::uint32_t>(static_cast<std::uint32_t>(item.payload.size()));  // originalSize
    w.put<std::uint32_t>(static_cast<std::uint32_t>(payload.size()));       // payloadSize
    w.pad(4);
    w.bytes.insert(w.bytes.end(), payload.begin(), payload.end());
  }
  return w.bytes;
}

std::vector<std::uint8_t> concat(const std::vector<std::vector<std::uint8_t>>& parts) {
  std::vector<std::uint8_t> all;
  for (const auto& p : parts) {
    all.insert(all.end(), p.begin(), p.end());
  }
  return all;
}

void writeBytes(const std::string& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes.data()),
            static_cast<std::streamsize>(bytes.size()));
}

std::vector<std::uint8_t> readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace sonarcarve::test
