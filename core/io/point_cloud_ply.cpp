#include "io/point_cloud_ply.h"

#include <bit>
#include <cstring>
#include <fstream>
#include <sstream>

#include "common/error.h"
#include "io/atomic_file.h"
#include "io/ply_check.h"

namespace sonarcarve {
namespace {

struct Property {
  std::string name;
  std::string type;
  int size = 0;
};

double decode(const char* bytes, const std::string& type, bool swap) {
  char b[8];
  const int n = plyTypeSize(type);
  for (int i = 0; i < n; ++i) {
    b[i] = swap ? bytes[n - 1 - i] : bytes[i];
  }
  const auto as = [&](auto value) {
    std::memcpy(&value, b, sizeof(value));
    return static_cast<double>(value);
  };
  if (type == "char" || type == "int8")
    return as(std::int8_t{});
  if (type == "uchar" || type == "uint8")
    return as(std::uint8_t{});
  if (type == "short" || type == "int16")
    return as(std::int16_t{});
  if (type == "ushort" || type == "uint16")
    return as(std::uint16_t{});
  if (type == "int" || type == "int32")
    return as(std::int32_t{});
  if (type == "uint" || type == "uint32")
    return as(std::uint32_t{});
  if (type == "float" || type == "float32")
    return as(float{});
  return as(double{});
}

}  // namespace

void writePointCloudPly(const std::filesystem::path& path, const PointCloud& cloud,
                        const std::map<std::string, std::vector<std::uint32_t>>& uint_properties) {
  const std::size_t n = cloud.positions.size();
  for (const auto& [name, values] : cloud.properties) {
    if (values.size() != n) {
      throw Error(path.string(), "property " + name, "expected one value per point");
    }
  }
  for (const auto& [name, values] : uint_properties) {
    if (values.size() != n) {
      throw Error(path.string(), "property " + name, "expected one value per point");
    }
  }
  std::ostringstream out;
  out << "ply\nformat binary_little_endian 1.0\ncomment SonarCarve point cloud: world frame, "
         "metres\nelement vertex "
      << n << "\nproperty float x\nproperty float y\nproperty float z\n";
  for (const auto& entry : cloud.properties) {
    out << "property float " << entry.first << "\n";
  }
  for (const auto& entry : uint_properties) {
    out << "property uint " << entry.first << "\n";
  }
  out << "end_header\n";
  std::string bytes = out.str();
  const std::size_t record = 4 * (3 + cloud.properties.size() + uint_properties.size());
  const std::size_t header = bytes.size();
  bytes.resize(header + record * n);
  static_assert(std::endian::native == std::endian::little, "writer assumes little-endian");
  for (std::size_t i = 0; i < n; ++i) {
    char* p = bytes.data() + header + i * record;
    std::memcpy(p, cloud.positions[i].data(), 12);
    p += 12;
    for (const auto& entry : cloud.properties) {
      std::memcpy(p, &entry.second[i], 4);
      p += 4;
    }
    for (const auto& entry : uint_properties) {
      std::memcpy(p, &entry.second[i], 4);
      p += 4;
    }
  }
  writeFileAtomically(path, bytes);
}

PointCloud readPointCloudPly(const std::filesystem::path& path) {
  const std::string file = path.string();
  if (!std::filesystem::is_regular_file(path)) {
    throw Error(file, "", "point cloud not found");
  }
  const PlyHeader header = checkPlyFile(path);  // well formed, body long enough
  if (header.elements.empty() || header.elements.front().name != "vertex") {
    throw Error(file, "header", "expected the vertex element first");
  }
  const std::string& format = header.format;
  const auto count = static_cast<std::size_t>(header.elements.front().count);
  std::vector<Property> props;
  for (const PlyProperty& p : header.elements.front().properties) {
    if (p.list) {
      throw Error(file, "header", "list property on vertices");
    }
    props.push_back({p.name, p.type, plyTypeSize(p.type)});
  }
  std::ifstream in(path, std::ios::binary);
  in.seekg(static_cast<std::streamoff>(header.body_offset));
  int ix = -1, iy = -1, iz = -1;
  for (std::size_t k = 0; k < props.size(); ++k) {
    if (props[k].name == "x")
      ix = static_cast<int>(k);
    if (props[k].name == "y")
      iy = static_cast<int>(k);
    if (props[k].name == "z")
      iz = static_cast<int>(k);
  }
  if (ix < 0 || iy < 0 || iz < 0) {
    throw Error(file, "header", "expected a vertex element with x, y and z");
  }
  PointCloud cloud;
  cloud.positions.resize(count);
  for (const auto& p : props) {
    if (p.name != "x" && p.name != "y" && p.name != "z") {
      cloud.properties[p.name].resize(count);
    }
  }
  std::vector<double> values(props.size());
  const bool ascii = format == "ascii";
  const bool swap = format == "binary_big_endian";
  std::size_t record = 0;
  for (const auto& p : props)
    record += static_cast<std::size_t>(p.size);
  std::vector<char> buffer(record);
  for (std::size_t i = 0; i < count; ++i) {
    if (ascii) {
      for (auto& v : values) {
        if (!(in >> v)) {
          throw Error(file, "vertex " + std::to_string(i),
                      "expected " + std::to_string(props.size()) + " numbers");
        }
      }
    } else {
      if (!in.read(buffer.data(), static_cast<std::streamsize>(record))) {
        throw Error(file, "vertex " + std::to_string(i), "file ends inside the vertex data");
      }
      std::size_t offset = 0;
      for (std::size_t k = 0; k < props.size(); ++k) {
        values[k] = decode(buffer.data() + offset, props[k].type, swap);
        offset += static_cast<std::size_t>(props[k].size);
      }
    }
    cloud.positions[i] =
        Eigen::Vector3d(values[static_cast<std::size_t>(ix)], values[static_cast<std::size_t>(iy)],
                        values[static_cast<std::size_t>(iz)])
            .cast<float>();
    for (std::size_t k = 0; k < props.size(); ++k) {
      auto it = cloud.properties.find(props[k].name);
      if (it != cloud.properties.end()) {
        it->second[i] = static_cast<float>(values[k]);
      }
    }
  }
  return cloud;
}

}  // namespace sonarcarve
