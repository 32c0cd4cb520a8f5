#include "support/pickle_writer.h"

#include <bit>
#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>

#include "common/angles.h"
#include "io/holoocean/holoocean_frames.h"
#include "support/test_support.h"

namespace sonarcarve::test {
namespace {

std::string littleEndian(std::uint64_t value, int bytes) {
  std::string out;
  for (int i = 0; i < bytes; ++i) {
    out += static_cast<char>((value >> (8 * i)) & 0xff);
  }
  return out;
}

// Bytes as Python 3 writes str(data, 'latin1') in UTF-8.
std::string latin1AsUtf8(std::string_view data) {
  std::string out;
  for (char ch : data) {
    const auto c = static_cast<unsigned char>(ch);
    if (c < 0x80) {
      out += static_cast<char>(c);
    } else {
      out += static_cast<char>(0xc0 | (c >> 6));
      out += static_cast<char>(0x80 | (c & 0x3f));
    }
  }
  return out;
}

}  // namespace

PickleWriter::PickleWriter(int protocol) : protocol_(protocol) {}

PickleWriter& PickleWriter::op(unsigned char opcode) {
  body_ += static_cast<char>(opcode);
  return *this;
}

PickleWriter& PickleWriter::raw(std::string_view bytes) {
  body_ += bytes;
  return *this;
}

PickleWriter& PickleWriter::text(std::string_view text) {
  if (text.size() < 256 && protocol_ >= 4) {
    op(0x8c).raw(littleEndian(text.size(), 1));  // SHORT_BINUNICODE
  } else {
    op('X').raw(littleEndian(text.size(), 4));  // BINUNICODE
  }
  return raw(text).memoize();
}

PickleWriter& PickleWriter::integer(std::int64_t value) {
  if (value >= 0 && value < 256) {
    return op('K').raw(littleEndian(static_cast<std::uint64_t>(value), 1));
  }
  if (value >= INT32_MIN && value <= INT32_MAX) {
    return op('J').raw(littleEndian(static_cast<std::uint32_t>(value), 4));
  }
  return op(0x8a).raw(littleEndian(8, 1)).raw(littleEndian(static_cast<std::uint64_t>(value), 8));
}

PickleWriter& PickleWriter::real(double value) {
  const auto bits = std::bit_cast<std::uint64_t>(value);
  std::string big;
  for (int i = 7; i >= 0; --i) {
    big += static_cast<char>((bits >> (8 * i)) & 0xff);
  }
  return op('G').raw(big);
}

PickleWriter& PickleWriter::bytes(std::string_view data) {
  if (protocol_ < 3) {  // Python 3's pickler in protocol 2: _codecs.encode(str, 'latin1')
    global("_codecs", "encode").text(latin1AsUtf8(data)).text("latin1").op(0x86).memoize();
    return op('R').memoize();
  }
  if (data.size() < 256) {
    op('C').raw(littleEndian(data.size(), 1));
  } else {
    op('B').raw(littleEndian(data.size(), 4));
  }
  return raw(data).memoize();
}

PickleWriter& PickleWriter::global(std::string_view module, std::string_view name) {
  if (protocol_ >= 4) {
    text(module).text(name).op(0x93);  // STACK_GLOBAL
  } else {
    op('c').raw(module).raw("\n").raw(name).raw("\n");
  }
  return memoize();
}

PickleWriter& PickleWriter::memoize() {
  if (protocol_ >= 4) {
    op(0x94);
  } else {
    op('q').raw(littleEndian(static_cast<std::uint64_t>(memo_), 1));
  }
  ++memo_;
  return *this;
}

PickleWriter& PickleWriter::dtype(std::string_view text_value, std::string_view order) {
  global("numpy", "dtype").text(text_value).op(0x89).op(0x88).op(0x87);
  memoize().op('R').memoize();
  op('(').integer(3).text(order).op('N').op('N').op('N').integer(-1).integer(-1).integer(0);
  return op('t').memoize().op('b');
}

PickleWriter& PickleWriter::reconstructedArray(const std::vector<std::int64_t>& shape,
                                               std::string_view dtype_text, std::string_view order,
                                               bool fortran_order, std::string_view data) {
  global("numpy.core.multiarray", "_reconstruct");
  global("numpy", "ndarray").integer(0).op(0x85).memoize().bytes("b").op(0x87).memoize();
  op('R').memoize();
  op('(').integer(1).op('(');
  for (std::int64_t d : shape) {
    integer(d);
  }
  op('t').memoize();
  dtype(dtype_text, order).op(fortran_order ? 0x88 : 0x89).bytes(data).op('t').memoize();
  return op('b');
}

PickleWriter& PickleWriter::numpyArray(const std::vector<double>& values,
                                       const std::vector<int>& shape, bool double_precision) {
  std::string data;
  for (double v : values) {
    if (double_precision) {
      data += littleEndian(std::bit_cast<std::uint64_t>(v), 8);
    } else {
      data += littleEndian(std::bit_cast<std::uint32_t>(static_cast<float>(v)), 4);
    }
  }
  const std::vector<std::int64_t> dims(shape.begin(), shape.end());
  const char* type = double_precision ? "f8" : "f4";
  if (protocol_ < 5) {
    return reconstructedArray(dims, type, "<", false, data);
  }
  // numpy.core.numeric._frombuffer(buffer, dtype, shape, 'C')
  global("numpy.core.numeric", "_frombuffer").op('(');
  op(0x96).raw(littleEndian(data.size(), 8)).raw(data).memoize();  // BYTEARRAY8
  dtype(type, "<").op('(');
  for (std::int64_t d : dims) {
    integer(d);
  }
  op('t').memoize();
  text("C").op('t').memoize();
  return op('R').memoize();
}

std::string PickleWriter::finish() const {
  std::string out = "\x80" + std::string(1, static_cast<char>(protocol_));
  const std::string body = body_ + ".";
  if (protocol_ >= 4) {
    out += '\x95' + littleEndian(body.size(), 8);  // one FRAME
  }
  return out + body;
}

std::string holoOceanFramePickle(const cv::Mat& holo_image, const Eigen::Matrix4d& pose,
                                 int protocol) {
  PickleWriter w(protocol);
  w.op('}').memoize().op('(');
  std::vector<double> pixels;
  for (int r = 0; r < holo_image.rows; ++r) {
    for (int c = 0; c < holo_image.cols; ++c) {
      pixels.push_back(holo_image.at<float>(r, c));
    }
  }
  w.text("ImagingSonar").numpyArray(pixels, {holo_image.rows, holo_image.cols});
  std::vector<double> matrix;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) {
      matrix.push_back(pose(r, c));
    }
  }
  w.text("PoseSensor").numpyArray(matrix, {4, 4});
  return w.op('u').finish();
}

std::string neusisConfigJson(const SonarModel& sonar) {
  const nlohmann::json imaging = {{"sensor_type", "ImagingSonar"},
                                  {"socket", "SonarSocket"},
                                  {"Hz", 1},
                                  {"configuration",
                                   {{"RangeMin", sonar.range().min_m},
                                    {"RangeMax", sonar.range().maxRange()},
                                    {"RangeBins", sonar.rows()},
                                    {"Azimuth", radToDeg(sonar.bearings().fieldOfView())},
                                    {"AzimuthBins", sonar.cols()},
                                    {"Elevation", radToDeg(sonar.verticalAperture())},
                                    {"AddSigma", 0},
                                    {"MultSigma", 0}}}};
  const nlohmann::json pose = {{"sensor_type", "PoseSensor"}, {"socket", "SonarSocket"}};
  const nlohmann::json config = {
      {"name", "sonarcarve-test"},
      {"world", "SimpleUnderwater"},
      {"main_agent", "auv0"},
      {"ticks_per_sec", 1},
      {"agents",
       {{{"agent_name", "auv0"}, {"agent_type", "HoveringAUV"}, {"sensors", {imaging, pose}}}}}};
  return config.dump(4);
}

void writeNeusisDataset(const Mission& mission, const std::filesystem::path& out, int protocol) {
  std::filesystem::create_directories(out / "Data");
  writeText(out / "Config.json", neusisConfigJson(mission.sonar));
  const NavTrack world = worldTrack(mission);
  for (std::size_t k = 0; k < mission.frames.size(); ++k) {
    const Frame frame = loadFrame(mission, k);
    cv::Mat holo;
    cv::flip(frame.image, holo, 1);  // our columns run port to starboard, HoloOcean's back
    const Eigen::Isometry3d T_ned =
        world.T_world_sonar(frame.time_s, mission.mounting.T_vehicle_sonar());
    char name[32];
    std::snprintf(name, sizeof(name), "%06zu.pkl", k);
    writeText(out / "Data" / name,
              holoOceanFramePickle(holo, holoOceanPoseFromNed(T_ned), protocol));
  }
}

}  // namespace sonarcarve::test
