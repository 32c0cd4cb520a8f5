#include "io/mesh/point_cloud_ply.h"

#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "common/error.h"
#include "geo/crs.h"
#include "io/files/atomic_file.h"
#include "io/files/finite_points.h"
#include "io/mesh/ply_check.h"
#include "sonar/mission_origin.h"

namespace sonarcarve {
namespace {

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
                        const std::map<std::string, std::vector<std::uint32_t>>& uint_properties,
                        const Triangles& triangles) {
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
         "metres\n";
  for (const std::string& comment : cloud.comments) {
    out << "comment " << comment << "\n";
  }
  out << "element vertex " << n << "\nproperty float x\nproperty float y\nproperty float z\n";
  for (const auto& entry : cloud.properties) {
    out << "property float " << entry.first << "\n";
  }
  for (const auto& entry : uint_properties) {
    out << "property uint " << entry.first << "\n";
  }
  if (!triangles.empty()) {
    out << "element face " << triangles.size() << "\nproperty list uchar int vertex_indices\n";
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
  for (const auto& t : triangles) {
    bytes.push_back(3);
    for (const std::uint32_t v : t) {
      const auto index = static_cast<std::int32_t>(v);
      bytes.append(reinterpret_cast<const char*>(&index), 4);
    }
  }
  writeFileAtomically(path, bytes);
}

namespace {

// Reads values of PLY scalar types from the body: words of text, or binary in either order.
class PlyValues {
 public:
  PlyValues(std::istream& in, const std::string& format)
      : in_(in), ascii_(format == "ascii"), swap_(format == "binary_big_endian") {}

  /// False at the end of the body or on a word that is not a number ("nan" and "inf" are
  /// numbers here, so that they reach the finiteness check and its message).
  bool read(const std::string& type, double& value) {
    if (ascii_) {
      std::string word;
      if (!(in_ >> word)) {
        return false;
      }
      const char* end = word.data() + word.size();
      const auto [ptr, ec] = std::from_chars(word.data(), end, value);
      return ec == std::errc() && ptr == end;
    }
    char bytes[8];
    if (!in_.read(bytes, plyTypeSize(type))) {
      return false;
    }
    value = decode(bytes, type, swap_);
    return true;
  }
  /// Whether anything but white space (ASCII) or any byte (binary) is left.
  bool more() {
    if (ascii_) {
      in_ >> std::ws;
    }
    return in_.peek() != std::char_traits<char>::eof();
  }
  /// The byte reached, from the file's start.
  std::uint64_t offset() { return static_cast<std::uint64_t>(in_.tellg()); }

 private:
  std::istream& in_;
  bool ascii_;
  bool swap_;
};

PointCloud readVertices(const std::string& file, const PlyElement& element, PlyValues& values,
                        const Eigen::Vector3d& origin_ned_m) {
  const auto count = static_cast<std::size_t>(element.count);
  int ix = -1, iy = -1, iz = -1;
  for (std::size_t k = 0; k < element.properties.size(); ++k) {
    const PlyProperty& p = element.properties[k];
    if (p.list) {
      throw Error(file, "header", "list property on vertices");
    }
    const int index = static_cast<int>(k);
    if (p.name == "x") {
      ix = index;
    } else if (p.name == "y") {
      iy = index;
    } else if (p.name == "z") {
      iz = index;
    }
  }
  if (ix < 0 || iy < 0 || iz < 0) {
    throw Error(file, "header", "expected a vertex element with x, y and z");
  }
  PointCloud cloud;
  cloud.positions.resize(count);
  for (const PlyProperty& p : element.properties) {
    if (p.name != "x" && p.name != "y" && p.name != "z") {
      cloud.properties[p.name].resize(count);
    }
  }
  std::vector<double> v(element.properties.size());
  for (std::size_t i = 0; i < count; ++i) {
    for (std::size_t k = 0; k < v.size(); ++k) {
      if (!values.read(element.properties[k].type, v[k])) {
        throw Error(file, "vertex " + std::to_string(i),
                    "expected " + std::to_string(v.size()) +
                        " numbers (the file ends or holds something else)");
      }
    }
    const auto at = [&](int k) { return v[static_cast<std::size_t>(k)]; };
    cloud.positions[i] = (Eigen::Vector3d(at(ix), at(iy), at(iz)) - origin_ned_m).cast<float>();
    requireFinitePoint(cloud.positions[i], file, "vertex " + std::to_string(i));
    for (std::size_t k = 0; k < v.size(); ++k) {
      auto it = cloud.properties.find(element.properties[k].name);
      if (it != cloud.properties.end()) {
        it->second[i] = static_cast<float>(v[k]);
      }
    }
  }
  return cloud;
}

// The corners of one face: the items of its vertex_indices (or vertex_index) list.
std::vector<double> readCorners(const std::string& file, const std::string& place,
                                const PlyElement& element, PlyValues& values) {
  std::vector<double> corners;
  for (const PlyProperty& p : element.properties) {
    double count = 0.0;
    if (!values.read(p.list ? p.count_type : p.type, count)) {
      throw Error(file, place, "the file ends or holds something else than a number");
    }
    if (!p.list) {
      continue;
    }
    if (!(count >= 0.0) || count != std::floor(count)) {
      throw Error(file, place, "expected a count of vertex indices");
    }
    const bool wanted = p.name == "vertex_indices" || p.name == "vertex_index";
    for (double k = 0; k < count; ++k) {
      double item = 0.0;
      if (!values.read(p.type, item)) {
        throw Error(file, place, "the file ends inside the face's list");
      }
      if (wanted) {
        corners.push_back(item);
      }
    }
  }
  return corners;
}

// The face element's polygons as triangles (fans); every index must name a vertex.
Triangles readFaces(const std::string& file, const PlyElement& element, std::size_t vertices,
                    PlyValues& values) {
  Triangles triangles;
  for (std::uint64_t f = 0; f < element.count; ++f) {
    const std::string place = "face " + std::to_string(f);
    const std::vector<double> corners = readCorners(file, place, element, values);
    if (corners.size() < 3) {
      throw Error(file, place, "expected at least 3 vertex indices");
    }
    for (const double c : corners) {
      if (!(c >= 0.0 && c < static_cast<double>(vertices)) || c != std::floor(c)) {
        std::ostringstream found;
        found << std::setprecision(20) << c;  // whole numbers in full
        throw Error(file, place,
                    "vertex index " + found.str() + " out of range: expected 0 to " +
                        std::to_string(vertices - 1));
      }
    }
    const auto index = [&](std::size_t k) { return static_cast<std::uint32_t>(corners[k]); };
    for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
      triangles.push_back({index(0), index(k), index(k + 1)});
    }
  }
  return triangles;
}

// Reads the elements after the first `read` ones, then requires the end of the file: data past
// what the header declares means its counts are wrong (a header declaring 5 faces where 12 are
// stored was read as 5 faces, silently).
void requireNoMoreData(const std::string& file, const PlyHeader& header, std::size_t read,
                       PlyValues& values) {
  for (std::size_t e = read; e < header.elements.size(); ++e) {
    const PlyElement& element = header.elements[e];
    for (std::uint64_t k = 0; k < element.count; ++k) {
      readCorners(file, element.name + " " + std::to_string(k), element, values);
    }
  }
  if (values.more()) {
    std::string counts;
    for (const PlyElement& element : header.elements) {
      counts += (counts.empty() ? "" : ", ") + element.name + " " + std::to_string(element.count);
    }
    throw Error(file, bytePlace(values.offset()),
                "data goes on past the elements the header declares (" + counts +
                    "): expected the file to end there (do the header's counts match the "
                    "data?)");
  }
}

PlyMesh readPly(const std::filesystem::path& path, bool with_faces,
                const Eigen::Vector3d& origin_ned_m) {
  const std::string file = path.string();
  const PlyHeader header = checkPlyFile(path);  // a regular file, well formed, body long enough
  if (header.elements.empty() || header.elements.front().name != "vertex") {
    throw Error(file, "header", "expected the vertex element first");
  }
  std::ifstream in(path, std::ios::binary);
  in.seekg(static_cast<std::streamoff>(header.body_offset));
  PlyValues values(in, header.format);
  PlyMesh mesh;
  mesh.vertices = readVertices(file, header.elements.front(), values, origin_ned_m);
  mesh.vertices.comments = header.comments;
  if (with_faces) {
    if (header.elements.size() < 2 || header.elements[1].name != "face") {
      throw Error(file, "header", "expected a face element after the vertices");
    }
    mesh.triangles = readFaces(file, header.elements[1], mesh.vertices.positions.size(), values);
  }
  requireNoMoreData(file, header, with_faces ? 2 : 1, values);
  return mesh;
}

}  // namespace

Eigen::Vector3d plyOrigin(const std::filesystem::path& path) {
  for (const std::string& comment : checkPlyFile(path).comments) {
    std::istringstream words(comment);
    std::string keyword;
    if (!(words >> keyword) || keyword != kOriginCommentKeyword) {
      continue;
    }
    Eigen::Vector3d origin;
    if (!(words >> origin.x() >> origin.y() >> origin.z()) || !origin.allFinite()) {
      throw Error(path.string(), "header comment '" + comment + "'",
                  "expected 'origin_ned_m N E D' with three finite numbers (metres)");
    }
    return origin;
  }
  return Eigen::Vector3d::Zero();
}

std::string plyCrs(const std::filesystem::path& path) {
  const std::string keyword = std::string(kCrsCommentKeyword) + " ";
  for (const std::string& comment : checkPlyFile(path).comments) {
    if (comment == kCrsCommentKeyword || comment.starts_with(keyword)) {
      const std::size_t start = comment.find_first_not_of(' ', keyword.size() - 1);
      if (start == std::string::npos) {
        throw Error(path.string(), "header comment '" + comment + "'",
                    "expected 'crs' and a CRS (EPSG:NNNN, a PROJ string or WKT)");
      }
      return comment.substr(start);
    }
  }
  return "";
}

PointCloud readPointCloudPly(const std::filesystem::path& path,
                             const Eigen::Vector3d& origin_ned_m) {
  return readPly(path, false, origin_ned_m).vertices;
}

PlyMesh readPlyMesh(const std::filesystem::path& path, const Eigen::Vector3d& origin_ned_m) {
  return readPly(path, true, origin_ned_m);
}

}  // namespace sonarcarve
