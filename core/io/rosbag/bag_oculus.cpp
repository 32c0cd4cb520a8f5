#include "io/rosbag/bag_oculus.h"

#include <algorithm>
#include <cstring>
#include <map>

#include "common/angles.h"
#include "common/error.h"
#include "io/files/yaml_fields.h"
#include "io/import.h"
#include "io/oculus/oculus_message.h"
#include "io/rosbag/cdr.h"

namespace sonarcarve {
namespace {

// The first messages of a topic looked at to recognise it: a raw data topic may start with a
// command sent to the sonar or a stray byte before its first ping.
constexpr std::size_t kOculusProbeMessages = 16;

std::uint32_t countAt(std::span<const std::uint8_t> cdr, std::size_t at, bool big_endian) {
  std::uint32_t value = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    const std::uint32_t byte = cdr[at + (big_endian ? i : 3 - i)];
    value = (value << 8) | byte;
  }
  return value;
}

std::string hex(unsigned value) {
  char text[16];
  std::snprintf(text, sizeof text, "0x%02X", value);
  return text;
}

// Whether a message definition (ros2msg text) starts with a std_msgs/Header: its first field,
// after comments, blank lines and constants ("uint8 DATA_IN=1").
bool definitionStartsWithHeader(const std::string& definition) {
  std::size_t begin = 0;
  while (begin < definition.size()) {
    const std::size_t end = std::min(definition.find('\n', begin), definition.size());
    std::string line = definition.substr(begin, end - begin);
    begin = end + 1;
    line = line.substr(0, line.find('#'));
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line.find('=') != std::string::npos) {
      continue;
    }
    const std::string type = line.substr(first, line.find_first_of(" \t", first) - first);
    return type == "Header" || type == "std_msgs/Header" || type == "std_msgs/msg/Header";
  }
  return false;
}

// The std_msgs/Header a message starts with, if it has one before its Oculus field. With the
// type's definition the answer is its first field; without one (a .db3 bag) the bytes must
// read as a header (nanoseconds below 10^9, a printable frame_id) that ends before the field.
std::optional<RosHeader> leadingHeader(std::span<const std::uint8_t> cdr, const OculusField& field,
                                       const BagTopic& topic) {
  const bool declared = !topic.definition.empty();
  if (declared && !definitionStartsWithHeader(topic.definition)) {
    return std::nullopt;
  }
  try {
    CdrReader in(cdr, topic.name, "");
    RosHeader header = readRosHeader(in);
    const bool before_field = 4 + in.offset() + 4 <= field.offset;
    const bool printable = std::all_of(header.frame_id.begin(), header.frame_id.end(),
                                       [](char c) { return c >= 0x20 && c < 0x7f; });
    if (declared || (before_field && printable && header.stamp_ns >= 0)) {
      return header;
    }
  } catch (const Error&) {
  }
  return std::nullopt;
}

// Error places inside a bag's Oculus message: "topic T, message 12 (byte 345), Oculus byte 16".
std::string oculusPlace(const std::string& place, const Error& e) {
  return place + (e.place().empty() ? std::string() : ", Oculus message " + e.place());
}

// The ping in a message, decoded by our Oculus decoder; errors name the bag and the message.
OculusPing decodeBagPing(std::span<const std::uint8_t> cdr, const OculusField& field,
                         bool with_image, const std::string& source, const std::string& place) {
  try {
    return decodeOculusPing(cdr.subspan(field.offset, field.size), 0, source, with_image);
  } catch (const Error& e) {
    throw Error(source, oculusPlace(place, e), e.message());
  }
}

bool sameGeometry(const OculusPing& ping, const SonarModel& sonar) {
  return oculusPingFormat(ping) == oculusPingFormat(sonar);
}

}  // namespace

std::optional<OculusField> findOculusField(std::span<const std::uint8_t> cdr) {
  if (cdr.size() < 4) {
    return std::nullopt;
  }
  const bool big_endian = cdr[1] == 0x00;
  // Counts are aligned to 4 bytes from the end of the 4-byte encapsulation header.
  for (std::size_t at = 4; at + 4 + 2 <= cdr.size(); at += 4) {
    const std::uint32_t count = countAt(cdr, at, big_endian);
    const std::size_t data = at + 4;
    if (count >= kOculusHeaderSize && count <= cdr.size() - data &&
        cdr[data] == (kOculusId & 0xff) && cdr[data + 1] == (kOculusId >> 8)) {
      return OculusField{data, count};
    }
  }
  return std::nullopt;
}

bool isOculusTopic(const RosBag& bag, std::size_t topic) {
  const BagTopic& t = bag.topics()[topic];
  if (rosMessageKind(t.type) != RosMessageKind::Other ||
      (!t.encoding.empty() && t.encoding != "cdr")) {
    return false;
  }
  std::size_t probed = 0;
  for (const BagMessage& m : bag.messages()) {
    if (m.topic != topic) {
      continue;
    }
    try {
      // A whole Oculus message (its header's size within the field), not two bytes that
      // happen to be the magic.
      const std::vector<std::uint8_t> cdr = bag.payload(m);
      if (const std::optional<OculusField> field = findOculusField(cdr)) {
        readOculusHeader(std::span(cdr).subspan(field->offset, field->size), 0, t.name);
        return true;
      }
    } catch (const Error&) {
      // An unreadable message says nothing of the topic; the next ones may.
    }
    if (++probed == kOculusProbeMessages) {
      break;
    }
  }
  return false;
}

BagOculusFrames indexOculusFrames(const RosBag& bag, std::size_t topic, BagTime clock,
                                  double time_offset_s, std::optional<double> aperture_deg,
                                  std::vector<std::string>& problems) {
  const std::string source = bag.path().string();
  const BagTopic& t = bag.topics()[topic];
  BagOculusFrames out;
  std::size_t other_geometry = 0;
  std::size_t without_header = 0;
  std::map<std::uint16_t, std::size_t> not_pings;  // msgId -> messages (0xFFFF: no Oculus bytes)
  std::optional<OculusPing> first;
  for (std::size_t i = 0; i < bag.messages().size(); ++i) {
    const BagMessage& m = bag.messages()[i];
    if (m.topic != topic) {
      continue;
    }
    const std::string place = "topic " + t.name + ", " + m.place;
    try {
      const std::vector<std::uint8_t> cdr = bag.payload(m);
      const std::optional<OculusField> field = findOculusField(cdr);
      if (!field) {
        ++not_pings[0xFFFF];
        continue;
      }
      const OculusMessageHeader head = [&] {
        try {
          return readOculusHeader(std::span(cdr).subspan(field->offset, field->size), 0, source);
        } catch (const Error& e) {
          throw Error(source, oculusPlace(place, e), e.message());
        }
      }();
      if (head.msg_id != kOculusSimplePingResult) {
        ++not_pings[head.msg_id];
        continue;
      }
      const OculusPing ping = decodeBagPing(cdr, *field, false, source, place);
      if (!out.sonar) {
        try {
          out.sonar = sonarModelFromPing(ping, aperture_deg);
        } catch (const Error& e) {
          throw Error(source, place, e.message());
        }
        first = ping;
      } else if (!sameGeometry(ping, *out.sonar)) {
        ++other_geometry;
        continue;
      }
      const std::optional<RosHeader> header = leadingHeader(cdr, *field, t);
      if (out.frames.empty()) {
        out.frame_id = header ? header->frame_id : "";
      }
      std::int64_t time_ns = m.receive_ns;
      if (clock == BagTime::Header) {
        if (header) {
          time_ns = header->stamp_ns;
        } else {
          ++without_header;
        }
      }
      out.frames.push_back({static_cast<double>(time_ns) * 1e-9 + time_offset_s, i});
    } catch (const Error& e) {
      problems.push_back(std::string(e.what()) + " (ping skipped)");
    }
  }
  if (!out.sonar) {
    throw Error(
        source, "topic " + t.name,
        "no readable Oculus ping" +
            (problems.empty() ? std::string() : " (first problem: " + problems.back() + ")"));
  }
  std::stable_sort(out.frames.begin(), out.frames.end(),
                   [](const BagFrameRef& a, const BagFrameRef& b) { return a.time_s < b.time_s; });
  out.notes.push_back("Oculus pings carried raw in " + (t.type.empty() ? "messages" : t.type) +
                      ", decoded by the Oculus reader: " + std::to_string(first->n_beams) +
                      " beams x " + std::to_string(first->n_ranges) +
                      " ranges, vertical aperture " +
                      shortestNumber(radToDeg(out.sonar->verticalAperture())) + " deg" +
                      (aperture_deg ? " (--aperture-deg)" : " assumed from the frequency"));
  if (without_header > 0) {
    out.notes.push_back(std::to_string(without_header) +
                        " pings in messages without a std_msgs/Header: their time is the bag's "
                        "receive time");
  }
  for (const auto& [id, count] : not_pings) {
    out.notes.push_back(std::to_string(count) + " messages of " + t.name +
                        (id == 0xFFFF ? " hold no Oculus message"
                                      : " hold Oculus message id " + hex(id) + ", not a ping") +
                        " (skipped)");
  }
  if (other_geometry > 0) {
    problems.push_back(source + ": topic " + t.name + ": " + std::to_string(other_geometry) +
                       " pings of another range window, bearing table or samples' scale than "
                       "the first (" +
                       std::to_string(first->n_beams) + " beams x " +
                       std::to_string(first->n_ranges) + " ranges, " +
                       out.sonar->intensityScale().describe() + ") left out");
  }
  return out;
}

cv::Mat bagOculusImage(std::span<const std::uint8_t> cdr, const SonarModel& sonar,
                       const std::string& source, const std::string& place) {
  const std::optional<OculusField> field = findOculusField(cdr);
  if (!field) {
    throw Error(source, place, "no Oculus message (magic 53 4F in a uint8[] field)");
  }
  const OculusPing ping = decodeBagPing(cdr, *field, true, source, place);
  if (!sameGeometry(ping, sonar)) {
    throw Error(source, place,
                std::to_string(ping.n_beams) + " beams x " + std::to_string(ping.n_ranges) +
                    " ranges, " + std::to_string(ping.sample_bytes * 8) +
                    "-bit samples of gammaCorrection " + std::to_string(ping.gamma) +
                    ": expected the first ping's geometry and samples' scale");
  }
  return ping.image;
}

}  // namespace sonarcarve
