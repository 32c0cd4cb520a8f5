#include "io/rosbag/bag_sonar.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <numeric>

#include "common/angles.h"
#include "common/error.h"
#include "common/input_limits.h"
#include "io/rosbag/ros_frames.h"
#include "sonar/sonar_ranges.h"

namespace sonarcarve {
namespace {

std::string fixed(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

// The message's own axes, when asked to judge: its beams lie in the Y-Z plane (Z forward) or
// in the X-Y plane (X forward).
SonarAxes resolveAxes(SonarAxes axes, const std::vector<Eigen::Vector3d>& directions) {
  if (axes != SonarAxes::Auto) {
    return axes;
  }
  double x = 0.0;
  double z = 0.0;
  for (const Eigen::Vector3d& d : directions) {
    x += std::abs(d.x());
    z += std::abs(d.z());
  }
  return z >= x ? SonarAxes::ZForward : SonarAxes::XForward;
}

RangeBins rangeBinsOf(const std::vector<float>& ranges, const std::string& source,
                      const std::string& place, std::vector<std::string>& notes) {
  if (ranges.size() < 2 || ranges.size() > static_cast<std::size_t>(kMaxRangeBins)) {
    throw Error(source, place,
                "ranges holds " + std::to_string(ranges.size()) + " values: expected 2 to " +
                    std::to_string(kMaxRangeBins) + " range bin centres");
  }
  const double first = ranges.front();
  const double resolution = (static_cast<double>(ranges.back()) - first) / (ranges.size() - 1);
  if (!(resolution > 0.0) || !std::isfinite(resolution) || !(first >= 0.0)) {
    throw Error(source, place,
                "ranges run from " + std::to_string(first) + " to " +
                    std::to_string(ranges.back()) + " m: expected increasing ranges from 0 m");
  }
  // Equal spacing within float32 rounding of the largest range (and 1 % of a bin).
  const double tolerance =
      std::max(0.01 * resolution, 4.0 * std::abs(static_cast<double>(ranges.back())) * 1.2e-7);
  for (std::size_t i = 0; i < ranges.size(); ++i) {
    const double expected = first + resolution * static_cast<double>(i);
    if (!(std::abs(ranges[i] - expected) <= tolerance)) {
      throw Error(source, place,
                  "ranges[" + std::to_string(i) + "] is " + std::to_string(ranges[i]) +
                      " m: expected equally spaced range bins (" + std::to_string(expected) +
                      " m); unequal bins are not supported");
    }
  }
  const double start = first - resolution / 2.0;
  if (start < -1e-6 * resolution) {
    // A bin centred under half a bin from the sonar would start before it: our bins start at 0.
    notes.push_back("ranges[0] is " + fixed(first, 4) + " m, less than half a bin (" +
                    fixed(resolution, 4) + " m): the bins are taken to start at 0 m, " +
                    fixed(-start, 4) + " m further than the message's centres");
  }
  return {std::max(0.0, start), resolution, static_cast<int>(ranges.size())};
}

// A message's transmit beam width: the median of its tx_beamwidths between 0 and pi, or
// nothing when it gives none.
std::optional<double> messageAperture(const ProjectedSonarImageMsg& msg) {
  std::vector<float> widths;
  for (const float w : msg.tx_beamwidths_rad) {
    if (std::isfinite(w) && w > 0.0F && w < std::numbers::pi) {
      widths.push_back(w);
    }
  }
  if (widths.empty()) {
    return std::nullopt;
  }
  std::nth_element(widths.begin(), widths.begin() + widths.size() / 2, widths.end());
  return widths[widths.size() / 2];
}

double apertureOf(const ProjectedSonarImageMsg& msg, std::optional<double> aperture_deg,
                  std::vector<std::string>& notes) {
  if (aperture_deg) {
    notes.push_back("vertical aperture " + fixed(*aperture_deg, 2) + " deg (--aperture-deg)");
    return degToRad(*aperture_deg);
  }
  const std::optional<double> width = messageAperture(msg);
  if (!width) {
    notes.push_back("vertical aperture " + fixed(kBagDefaultApertureDeg, 2) +
                    " deg assumed: the messages give no tx_beamwidths; override it with "
                    "--aperture-deg");
    return degToRad(kBagDefaultApertureDeg);
  }
  const double aperture = *width;
  notes.push_back("vertical aperture " + fixed(radToDeg(aperture), 2) +
                  " deg: the transmit beam width (ping_info.tx_beamwidths)");
  return aperture;
}

template <typename T>
float sampleAs(const std::uint8_t* p, bool swap) {
  T value{};
  std::memcpy(&value, p, sizeof(T));
  if (swap) {
    auto* b = reinterpret_cast<unsigned char*>(&value);
    std::reverse(b, b + sizeof(T));
  }
  return static_cast<float>(value);
}

float sample(const std::uint8_t* p, std::uint32_t dtype, bool swap) {
  switch (static_cast<SonarDtype>(dtype)) {
    case SonarDtype::UInt8:
      return *p;
    case SonarDtype::Int8:
      return static_cast<float>(static_cast<std::int8_t>(*p));
    case SonarDtype::UInt16:
      return sampleAs<std::uint16_t>(p, swap);
    case SonarDtype::Int16:
      return sampleAs<std::int16_t>(p, swap);
    case SonarDtype::UInt32:
      return sampleAs<std::uint32_t>(p, swap);
    case SonarDtype::Int32:
      return sampleAs<std::int32_t>(p, swap);
    case SonarDtype::UInt64:
      return sampleAs<std::uint64_t>(p, swap);
    case SonarDtype::Int64:
      return sampleAs<std::int64_t>(p, swap);
    case SonarDtype::Float32:
      return sampleAs<float>(p, swap);
    case SonarDtype::Float64:
      return sampleAs<double>(p, swap);
  }
  return 0.0F;
}

}  // namespace

BagSonarGeometry bagSonarGeometry(const ProjectedSonarImageMsg& msg, SonarAxes axes,
                                  ImageLayout layout, std::optional<double> aperture_deg,
                                  const std::string& sonar_id, const std::string& source,
                                  const std::string& place) {
  const std::size_t beams = msg.beam_directions.size();
  if (beams == 0 || beams > static_cast<std::size_t>(kMaxBeams) || msg.beam_count != beams) {
    throw Error(source, place,
                "image.beam_count " + std::to_string(msg.beam_count) + " and " +
                    std::to_string(beams) + " beam_directions: expected the same number, 1 to " +
                    std::to_string(kMaxBeams));
  }
  const SonarAxes resolved = resolveAxes(axes, msg.beam_directions);
  std::vector<double> bearings;
  for (const Eigen::Vector3d& d : msg.beam_directions) {
    bearings.push_back(bearingOfBeamDirection(d, resolved));
  }
  std::vector<int> order(beams);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return bearings[a] < bearings[b]; });
  std::vector<double> centres;
  for (const int b : order) {
    if (!std::isfinite(bearings[b]) || (!centres.empty() && bearings[b] <= centres.back())) {
      throw Error(source, place,
                  "beam_directions[" + std::to_string(b) +
                      "] repeats a bearing or is not finite: expected one direction per beam");
    }
    centres.push_back(bearings[b]);
  }
  std::vector<std::string> notes;
  const RangeBins range = rangeBinsOf(msg.ranges_m, source, place, notes);
  const double aperture = apertureOf(msg, aperture_deg, notes);
  // Against the ranges a mission.yaml is held to (sonar/sonar_ranges.h).
  const RecordedGeometry recorded{
      .near_range_m = {"ranges (the first)", range.min_m},
      .range_resolution_m = {"ranges (their spacing)", range.resolution_m},
      .bins = range.count,
      .field_of_view_deg = {"beam_directions (their span of bearings)",
                            radToDeg(centres.back() - centres.front())},
      .vertical_aperture_deg = {aperture_deg ? "--aperture-deg" : "ping_info.tx_beamwidths",
                                radToDeg(aperture)}};
  if (const auto problem = recordedGeometryProblem(recorded)) {
    throw Error(source, place, *problem);
  }
  BagSonarGeometry g{SonarModel(sonar_id, range, BearingTable::fromCentres(centres), aperture),
                     resolved,
                     layout,
                     msg.beam_directions,
                     order,
                     msg.ranges_m.size(),
                     {},
                     !aperture_deg};
  g.notes.push_back(
      std::string("sonar axes ") + std::string(toString(resolved)) +
      (axes == SonarAxes::Auto
           ? (resolved == SonarAxes::ZForward
                  ? " (chosen: the beam directions lie in the Y-Z plane, as the message comment "
                    "says)"
                  : " (chosen: the beam directions lie in the X-Y plane, X forward)")
       : resolved == SonarAxes::Frd ? ""
                                    : " (--sonar-axes)") +
      "; bearings " + fixed(radToDeg(centres.front()), 2) + " to " +
      fixed(radToDeg(centres.back()), 2) + " deg, positive to starboard");
  g.notes.push_back("image layout " + std::string(toString(layout)) +
                    (layout == ImageLayout::RangeMajor
                         ? " (data[range * beams + beam], as the reference drivers write; "
                           "--image-layout beam-major for the other)"
                         : " (data[beam * ranges + range], --image-layout)"));
  g.notes.insert(g.notes.end(), notes.begin(), notes.end());
  return g;
}

void checkBagSonarMessage(const ProjectedSonarImageMsg& msg, const BagSonarGeometry& g,
                          const std::string& source, const std::string& place) {
  const std::size_t beams = g.beam_directions.size();
  if (msg.beam_directions.size() != beams || msg.ranges_m.size() != g.ranges ||
      msg.beam_count != beams) {
    throw Error(source, place,
                std::to_string(msg.beam_directions.size()) + " beams x " +
                    std::to_string(msg.ranges_m.size()) +
                    " ranges: expected the first sonar "
                    "message's " +
                    std::to_string(beams) + " x " + std::to_string(g.ranges));
  }
  for (std::size_t b = 0; b < beams; ++b) {
    if ((msg.beam_directions[b] - g.beam_directions[b]).norm() > 1e-6) {
      throw Error(source, place,
                  "beam_directions[" + std::to_string(b) +
                      "] differs from the first sonar message's: one geometry per bag is read");
    }
  }
  // Not used for the geometry (ranges are in metres), but a value out of any sea is a corrupt
  // message; 0 is a driver that does not fill it in.
  if (msg.sound_speed_mps != 0.0F) {
    if (const auto problem = outsideRange(msg.sound_speed_mps, kSoundSpeed)) {
      throw Error(source, place, "sound_speed: " + *problem + " (or 0 when not known)");
    }
  }
  // A later message's aperture is not used (one geometry per bag), but one out of any sonar is
  // a corrupt message, as the first's would be.
  if (const auto aperture = messageAperture(msg); aperture && g.aperture_from_messages) {
    if (const auto problem = outsideRange(radToDeg(*aperture), kVerticalAperture)) {
      throw Error(source, place, "ping_info.tx_beamwidths: " + *problem);
    }
  }
  const std::size_t size = sonarDtypeSize(msg.dtype);
  if (size == 0) {
    throw Error(
        source, place,
        "image.dtype " + std::to_string(msg.dtype) + ": expected 0 to 9 (uint8 ... float64)");
  }
  const std::size_t samples = beams * g.ranges;
  if (msg.data.size() != samples * size) {
    throw Error(source, place,
                "image.data holds " + std::to_string(msg.data.size()) + " bytes: expected " +
                    std::to_string(beams) + " beams x " + std::to_string(g.ranges) + " ranges x " +
                    std::to_string(size) + " bytes");
  }
}

cv::Mat bagSonarImage(const ProjectedSonarImageMsg& msg, const BagSonarGeometry& g,
                      const std::string& source, const std::string& place) {
  checkBagSonarMessage(msg, g, source, place);
  const std::size_t beams = g.beam_directions.size();
  const std::size_t size = sonarDtypeSize(msg.dtype);
  const bool swap = msg.is_bigendian != (std::endian::native == std::endian::big);
  cv::Mat image(static_cast<int>(g.ranges), static_cast<int>(beams), CV_32F);
  for (int r = 0; r < image.rows; ++r) {
    auto* row = image.ptr<float>(r);
    for (int c = 0; c < image.cols; ++c) {
      const auto b = static_cast<std::size_t>(g.beam_of_column[static_cast<std::size_t>(c)]);
      const std::size_t k = g.layout == ImageLayout::RangeMajor
                                ? static_cast<std::size_t>(r) * beams + b
                                : b * g.ranges + static_cast<std::size_t>(r);
      const float v = sample(msg.data.data() + k * size, msg.dtype, swap);
      row[c] = std::isfinite(v) ? v : 0.0F;
    }
  }
  return image;
}

}  // namespace sonarcarve
