#include "mesh/mesh_export.h"

#include <cmath>
#include <cstring>
#include <iomanip>
#include <sstream>

#include "common/error.h"
#include "common/number_text.h"
#include "io/files/atomic_file.h"
#include "io/mesh/ply_check.h"
#include "io/mesh/point_cloud_ply.h"
#include "sonar/mission_origin.h"

namespace sonarcarve {
namespace {

// What is added to a local position before the frame: the mission origin, for world output.
Eigen::Vector3d addedOrigin(const ExportOptions& o) {
  return o.add_mission_origin ? o.mission_origin_ned_m : Eigen::Vector3d::Zero();
}

// A position in the output frame, in double. Zero offsets are not added, so that a local
// export keeps every float to the bit (a -0 stays -0).
Eigen::Vector3d toFrame(const Eigen::Vector3f& p_local, const ExportOptions& o) {
  Eigen::Vector3d q = p_local.cast<double>();
  if (o.add_mission_origin && !o.mission_origin_ned_m.isZero()) {
    q += o.mission_origin_ned_m;
  }
  if (!o.origin_ned_m.isZero()) {
    q -= o.origin_ned_m;
  }
  return o.frame == "zup" ? Eigen::Vector3d(q.y(), q.x(), -q.z()) : q;
}

bool insideCrop(const Eigen::Vector3f& p_local, const ExportOptions& o) {
  return !o.crop_ned_m || o.crop_ned_m->contains(p_local.cast<double>() + addedOrigin(o));
}

// The origin to add back to what the file holds to get world NED (its PLY comment), or zero.
Eigen::Vector3d fileOrigin(const ExportOptions& o) {
  return (o.add_mission_origin ? Eigen::Vector3d::Zero() : o.mission_origin_ned_m) + o.origin_ned_m;
}

Eigen::Vector3f directionToFrame(const Eigen::Vector3f& d_ned, const ExportOptions& o) {
  return o.frame == "zup" ? Eigen::Vector3f(d_ned.y(), d_ned.x(), -d_ned.z()) : d_ned;
}

// Vertices (with normals for a mesh) and triangles in the output frame, cropped.
struct Prepared {
  std::vector<Eigen::Vector3d> positions;  ///< in the output frame, double
  std::vector<Eigen::Vector3f> normals;    ///< empty for points
  std::vector<float> intensity;
  std::vector<std::uint32_t> views;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  bool world_double = false;  ///< positions written as double
  std::string kind;           ///< "mesh" or "points", for the header's first comment
  Eigen::Vector3d origin_comment = Eigen::Vector3d::Zero();
};

Prepared preparedFor(const ExportOptions& o, const char* kind) {
  Prepared out;
  out.world_double = o.add_mission_origin;
  out.kind = kind;
  out.origin_comment = fileOrigin(o);
  return out;
}

// The mesh in the output frame, cropped; vertices no triangle uses are dropped.
Prepared prepared(const Mesh& mesh, const ExportOptions& o) {
  Prepared out = preparedFor(o, "mesh");
  std::vector<std::int64_t> remap(mesh.vertices.size(), -1);
  for (const auto& t : mesh.triangles) {
    if (!insideCrop(mesh.vertices[t[0]], o) || !insideCrop(mesh.vertices[t[1]], o) ||
        !insideCrop(mesh.vertices[t[2]], o)) {
      continue;
    }
    std::array<std::uint32_t, 3> nt{};
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = t[static_cast<std::size_t>(k)];
      if (remap[v] < 0) {
        remap[v] = static_cast<std::int64_t>(out.positions.size());
        out.positions.push_back(toFrame(mesh.vertices[v], o));
        out.normals.push_back(directionToFrame(mesh.normals[v], o));
        out.intensity.push_back(mesh.intensity[v]);
        out.views.push_back(mesh.views[v]);
      }
      nt[static_cast<std::size_t>(k)] = static_cast<std::uint32_t>(remap[v]);
    }
    out.triangles.push_back(nt);
  }
  return out;
}

Prepared prepared(const SurfacePoints& points, const ExportOptions& o) {
  Prepared out = preparedFor(o, "points");
  for (const SurfacePoint& p : points) {
    if (insideCrop(p.position_m, o)) {
      out.positions.push_back(toFrame(p.position_m, o));
      out.intensity.push_back(p.intensity);
      out.views.push_back(p.views);
    }
  }
  return out;
}

// x, y, z as text: floats as before (9 digits), world coordinates in double to the micrometre.
void writeCoordinates(std::ostream& out, const Eigen::Vector3d& p, bool world_double) {
  if (world_double) {
    out << std::fixed << std::setprecision(6) << p.x() << ' ' << p.y() << ' ' << p.z()
        << std::defaultfloat << std::setprecision(9);
  } else {
    const Eigen::Vector3f f = p.cast<float>();
    out << f.x() << ' ' << f.y() << ' ' << f.z();
  }
}

std::string plyText(const Prepared& m, bool ascii) {
  const bool mesh = !m.normals.empty() || !m.triangles.empty();
  const char* coordinate = m.world_double ? "double" : "float";
  std::ostringstream out;
  out << "ply\nformat " << (ascii ? "ascii" : "binary_little_endian") << " 1.0\n"
      << "comment SonarCarve " << m.kind << ", metres\n";
  if (!m.origin_comment.isZero()) {
    out << "comment " << originComment(m.origin_comment) << "\n";
  }
  out << "element vertex " << m.positions.size() << "\n";
  for (const char* axis : {"x", "y", "z"}) {
    out << "property " << coordinate << " " << axis << "\n";
  }
  if (mesh) {
    out << "property float nx\nproperty float ny\nproperty float nz\n";
  }
  out << "property float intensity\nproperty uint views\n";
  if (mesh) {
    out << "element face " << m.triangles.size() << "\nproperty list uchar int vertex_indices\n";
  }
  out << "end_header\n";
  std::string bytes = out.str();
  if (ascii) {
    std::ostringstream body;
    body.precision(9);
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
      writeCoordinates(body, m.positions[i], m.world_double);
      if (mesh) {
        const auto& n = m.normals[i];
        body << ' ' << n.x() << ' ' << n.y() << ' ' << n.z();
      }
      body << ' ' << m.intensity[i] << ' ' << m.views[i] << '\n';
    }
    for (const auto& t : m.triangles) {
      body << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    }
    return bytes + body.str();
  }
  const auto append = [&](const void* data, std::size_t n) {
    bytes.append(static_cast<const char*>(data), n);
  };
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    if (m.world_double) {
      append(m.positions[i].data(), 24);
    } else {
      const Eigen::Vector3f f = m.positions[i].cast<float>();
      append(f.data(), 12);
    }
    if (mesh) {
      append(m.normals[i].data(), 12);
    }
    append(&m.intensity[i], 4);
    append(&m.views[i], 4);
  }
  for (const auto& t : m.triangles) {
    const std::uint8_t three = 3;
    append(&three, 1);
    for (std::uint32_t v : t) {
      const auto index = static_cast<std::int32_t>(v);
      append(&index, 4);
    }
  }
  return bytes;
}

// Binary STL: an 80-byte header, the triangle count, then per triangle its normal, its three
// corners (float32, little-endian) and a zero attribute word.
std::string stlBytes(const Prepared& p) {
  std::vector<Eigen::Vector3f> vertices;
  for (const Eigen::Vector3d& v : p.positions) {
    vertices.push_back(v.cast<float>());
  }
  std::string bytes(80, ' ');
  bytes.replace(0, 30, "SonarCarve mesh, metres       ");
  const auto append = [&](const void* data, std::size_t n) {
    bytes.append(static_cast<const char*>(data), n);
  };
  const auto count = static_cast<std::uint32_t>(p.triangles.size());
  append(&count, 4);
  for (const auto& t : p.triangles) {
    const Eigen::Vector3f& a = vertices[t[0]];
    const Eigen::Vector3f normal = (vertices[t[1]] - a).cross(vertices[t[2]] - a).normalized();
    append(normal.data(), 12);
    for (std::uint32_t v : t) {
      append(vertices[v].data(), 12);
    }
    const std::uint16_t attribute = 0;
    append(&attribute, 2);
  }
  return bytes;
}

// Wavefront OBJ: vertices, vertex normals, and faces numbered from 1.
std::string objText(const Prepared& m) {
  std::ostringstream out;
  out.precision(9);
  out << "# SonarCarve mesh, metres\n";
  if (!m.origin_comment.isZero()) {
    out << "# " << originComment(m.origin_comment) << "\n";
  }
  for (const auto& v : m.positions) {
    out << "v ";
    writeCoordinates(out, v, m.world_double);
    out << '\n';
  }
  for (const auto& n : m.normals) {
    out << "vn " << n.x() << ' ' << n.y() << ' ' << n.z() << '\n';
  }
  for (const auto& t : m.triangles) {
    out << 'f';
    for (std::uint32_t v : t) {
      out << ' ' << v + 1 << "//" << v + 1;
    }
    out << '\n';
  }
  return out.str();
}

}  // namespace

void ExportOptions::validate() const {
  if (format != "ply" && format != "ply-ascii" && format != "stl" && format != "obj") {
    throw Error("export", "format", "expected ply, ply-ascii, stl or obj");
  }
  if (frame != "ned" && frame != "zup") {
    throw Error("export", "frame", "expected ned or zup");
  }
  if (!mission_origin_ned_m.allFinite() || !origin_ned_m.allFinite()) {
    throw Error("export", "origin", "expected finite origins (metres, NED)");
  }
  if (add_mission_origin && format == "stl" && !mission_origin_ned_m.isZero()) {
    throw Error("export", "format stl",
                "STL holds float32 coordinates, which keep only about " +
                    shortestNumber(std::ldexp(mission_origin_ned_m.cwiseAbs().maxCoeff(), -24)) +
                    " m at the mission origin " + nedText(mission_origin_ned_m) +
                    ": expected ply, ply-ascii or obj for world coordinates");
  }
}

std::string formatOfPath(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".ply" || ext == ".stl" || ext == ".obj") {
    return ext.substr(1);
  }
  throw Error(path.string(), "", "unknown file type: expected .ply, .stl or .obj");
}

void exportMesh(const Mesh& mesh, const std::filesystem::path& path, const ExportOptions& options) {
  options.validate();
  const Prepared m = prepared(mesh, options);
  if (m.triangles.empty()) {
    throw Error(path.string(), "", "no triangle to export (empty mesh or crop box)");
  }
  if (options.format == "stl") {
    writeFileAtomically(path, stlBytes(m));
  } else if (options.format == "obj") {
    writeFileAtomically(path, objText(m));
  } else {
    writeFileAtomically(path, plyText(m, options.format == "ply-ascii"));
  }
}

void exportPoints(const SurfacePoints& points, const std::filesystem::path& path,
                  const ExportOptions& options) {
  options.validate();
  if (options.format != "ply" && options.format != "ply-ascii") {
    throw Error(path.string(), "", "points are exported as PLY only");
  }
  writeFileAtomically(path, plyText(prepared(points, options), options.format == "ply-ascii"));
}

Mesh readMeshPly(const std::filesystem::path& path) {
  const PlyMesh ply = readPlyMesh(path);
  const PointCloud& cloud = ply.vertices;  // positions and their properties
  Mesh mesh;
  mesh.vertices = cloud.positions;
  const auto property = [&](const char* name) {
    const auto it = cloud.properties.find(name);
    return it == cloud.properties.end() ? std::vector<float>(cloud.positions.size(), 0.0f)
                                        : it->second;
  };
  const auto nx = property("nx"), ny = property("ny"), nz = property("nz");
  const auto views = property("views");
  mesh.intensity = property("intensity");
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    mesh.normals.emplace_back(nx[i], ny[i], nz[i]);
    mesh.views.push_back(static_cast<std::uint32_t>(views[i]));
  }
  mesh.triangles = ply.triangles;
  if (mesh.triangles.empty()) {
    throw Error(path.string(), "", "no triangles: expected a mesh PLY");
  }
  return mesh;
}

}  // namespace sonarcarve
