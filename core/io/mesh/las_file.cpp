#include "io/mesh/las_file.h"

#include <array>
#include <cmath>
#include <cstring>
#include <limits>

#include "common/error.h"
#include "io/files/atomic_file.h"

namespace sonarcarve {
namespace {

constexpr std::size_t kHeaderSize = 375;
constexpr std::size_t kVlrHeaderSize = 54;
constexpr std::size_t kPointSize = 30;  // point data record format 6
constexpr std::uint8_t kPointFormat = 6;
constexpr std::uint16_t kGlobalEncodingWkt = 1u << 4;
constexpr std::uint16_t kWktRecordId = 2112;
constexpr std::array<double, 2> kScales = {0.0001, 0.001};
// Rounded coordinates stay a little inside int32, so that a point on the box's edge never wraps.
constexpr double kInt32Reach = 2.0e9;

// Little-endian encoding into a growing byte string (x86 and ARM: the host's order).
class Bytes {
 public:
  template <typename T>
  void put(T value) {
    char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    bytes_.append(raw, sizeof(T));
  }
  // A fixed-size text field, NUL-padded (cut to its size).
  void text(const std::string& s, std::size_t size) {
    const std::string field = s.substr(0, size);
    bytes_ += field;
    bytes_.append(size - field.size(), '\0');
  }
  void zeros(std::size_t n) { bytes_.append(n, '\0'); }
  std::size_t size() const { return bytes_.size(); }
  std::string take() { return std::move(bytes_); }

 private:
  std::string bytes_;
};

struct Quantisation {
  Eigen::Vector3d scale, offset;
};

Quantisation quantisationOf(const std::vector<LasPoint>& points, const std::string& target) {
  Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d& p = points[i].xyz;
    if (!p.allFinite()) {
      throw Error(target, "point " + std::to_string(i), "expected finite coordinates");
    }
    lo = i == 0 ? p : lo.cwiseMin(p);
    hi = i == 0 ? p : hi.cwiseMax(p);
  }
  Quantisation q;
  q.offset = ((lo + hi) / 2.0).array().round();
  const double half_extent = std::max((hi - q.offset).maxCoeff(), (q.offset - lo).maxCoeff());
  const double scale = lasScaleFor(half_extent);
  if (scale == 0.0) {
    throw Error(target, "extent",
                "the points span " + std::to_string(2.0 * half_extent) +
                    " m, beyond what LAS's int32 coordinates hold at 1 mm: expected a cloud "
                    "within 4000 km");
  }
  q.scale = Eigen::Vector3d::Constant(scale);
  return q;
}

void putHeader(Bytes& out, const LasCloud& cloud, const Quantisation& q, const Eigen::Vector3d& lo,
               const Eigen::Vector3d& hi, std::uint32_t vlrs, std::uint32_t point_offset) {
  out.text("LASF", 4);
  out.put<std::uint16_t>(0);  // file source ID
  out.put<std::uint16_t>(kGlobalEncodingWkt);
  out.zeros(16);  // project ID (GUID)
  out.put<std::uint8_t>(1);
  out.put<std::uint8_t>(4);
  out.text("SonarCarve export", 32);  // system identifier
  out.text(cloud.generating_software, 32);
  out.put<std::uint16_t>(0);  // creation day of year: unknown
  out.put<std::uint16_t>(0);  // creation year: unknown
  out.put<std::uint16_t>(static_cast<std::uint16_t>(kHeaderSize));
  out.put<std::uint32_t>(point_offset);
  out.put<std::uint32_t>(vlrs);
  out.put<std::uint8_t>(kPointFormat);
  out.put<std::uint16_t>(static_cast<std::uint16_t>(kPointSize));
  out.zeros(4 + 5 * 4);  // legacy point counts: 0 for formats 6 to 10
  for (int a = 0; a < 3; ++a)
    out.put<double>(q.scale[a]);
  for (int a = 0; a < 3; ++a)
    out.put<double>(q.offset[a]);
  for (int a = 0; a < 3; ++a) {
    out.put<double>(hi[a]);
    out.put<double>(lo[a]);
  }
  out.put<std::uint64_t>(0);  // start of waveform data
  out.put<std::uint64_t>(0);  // start of the first EVLR
  out.put<std::uint32_t>(0);  // EVLRs
  const auto count = static_cast<std::uint64_t>(cloud.points.size());
  out.put<std::uint64_t>(count);
  out.put<std::uint64_t>(count);  // points by return: all are first returns
  out.zeros(14 * 8);
}

void putWktRecord(Bytes& out, const std::string& wkt) {
  out.put<std::uint16_t>(0);  // reserved
  out.text("LASF_Projection", 16);
  out.put<std::uint16_t>(kWktRecordId);
  out.put<std::uint16_t>(static_cast<std::uint16_t>(wkt.size() + 1));
  out.text("OGC coordinate system WKT", 32);
  out.text(wkt, wkt.size() + 1);
}

}  // namespace

double lasScaleFor(double half_extent_m) {
  for (double scale : kScales) {
    if (half_extent_m / scale + 1.0 <= kInt32Reach) {
      return scale;
    }
  }
  return 0.0;
}

std::string lasBytes(const LasCloud& cloud, const std::string& target) {
  if (cloud.crs_wkt.size() + 1 > std::numeric_limits<std::uint16_t>::max()) {
    throw Error(target, "crs", "the CRS's WKT is over 65534 bytes: expected a shorter CRS");
  }
  const Quantisation q = quantisationOf(cloud.points, target);
  std::vector<std::array<std::int32_t, 3>> stored;
  stored.reserve(cloud.points.size());
  Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < cloud.points.size(); ++i) {
    std::array<std::int32_t, 3> xyz{};
    Eigen::Vector3d back;
    for (int a = 0; a < 3; ++a) {
      const double units = std::round((cloud.points[i].xyz[a] - q.offset[a]) / q.scale[a]);
      xyz[static_cast<std::size_t>(a)] = static_cast<std::int32_t>(units);
      back[a] = q.offset[a] + units * q.scale[a];
    }
    lo = i == 0 ? back : lo.cwiseMin(back);
    hi = i == 0 ? back : hi.cwiseMax(back);
    stored.push_back(xyz);
  }
  const bool with_crs = !cloud.crs_wkt.empty();
  const std::size_t vlr_bytes = with_crs ? kVlrHeaderSize + cloud.crs_wkt.size() + 1 : 0;
  Bytes out;
  putHeader(out, cloud, q, lo, hi, with_crs ? 1u : 0u,
            static_cast<std::uint32_t>(kHeaderSize + vlr_bytes));
  if (with_crs) {
    putWktRecord(out, cloud.crs_wkt);
  }
  for (std::size_t i = 0; i < cloud.points.size(); ++i) {
    const LasPoint& p = cloud.points[i];
    for (std::int32_t v : stored[i])
      out.put<std::int32_t>(v);
    out.put<std::uint16_t>(p.intensity);
    out.put<std::uint8_t>(0x11);  // return 1 of 1
    out.put<std::uint8_t>(0);     // classification flags, channel, scan direction, edge
    out.put<std::uint8_t>(static_cast<std::uint8_t>(p.classification));
    out.put<std::uint8_t>(p.user_data);
    out.put<std::int16_t>(0);   // scan angle
    out.put<std::uint16_t>(0);  // point source ID
    out.put<double>(0.0);       // GPS time
  }
  return out.take();
}

void writeLasFile(const std::filesystem::path& path, const LasCloud& cloud) {
  writeFileAtomically(path, lasBytes(cloud, path.string()));
}

}  // namespace sonarcarve
