#include "mesh/mesh_export.h"

#include <cstring>
#include <sstream>

#include "common/error.h"
#include "io/files/atomic_file.h"
#include "io/mesh/ply_check.h"
#include "io/mesh/point_cloud_ply.h"

namespace sonarcarve {
namespace {

Eigen::Vector3f toFrame(const Eigen::Vector3f& p_ned, const ExportOptions& o) {
  const Eigen::Vector3f q = p_ned - o.origin_ned_m.cast<float>();
  return o.frame == "zup" ? Eigen::Vector3f(q.y(), q.x(), -q.z()) : q;
}

Eigen::Vector3f directionToFrame(const Eigen::Vector3f& d_ned, const ExportOptions& o) {
  return o.frame == "zup" ? Eigen::Vector3f(d_ned.y(), d_ned.x(), -d_ned.z()) : d_ned;
}

// The mesh in the output frame, cropped; vertices no triangle uses are dropped.
Mesh prepared(const Mesh& mesh, const ExportOptions& o) {
  Mesh out;
  std::vector<std::int64_t> remap(mesh.vertices.size(), -1);
  const auto inside = [&](std::uint32_t v) {
    return !o.crop_ned_m || o.crop_ned_m->contains(mesh.vertices[v].cast<double>());
  };
  for (const auto& t : mesh.triangles) {
    if (!inside(t[0]) || !inside(t[1]) || !inside(t[2])) {
      continue;
    }
    std::array<std::uint32_t, 3> nt{};
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = t[static_cast<std::size_t>(k)];
      if (remap[v] < 0) {
        remap[v] = static_cast<std::int64_t>(out.vertices.size());
        out.vertices.push_back(toFrame(mesh.vertices[v], o));
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

std::string plyText(const Mesh& m, bool ascii) {
  std::ostringstream out;
  out << "ply\nformat " << (ascii ? "ascii" : "binary_little_endian") << " 1.0\n"
      << "comment SonarCarve mesh, metres\nelement vertex " << m.vertices.size() << "\n"
      << "property float x\nproperty float y\nproperty float z\n"
      << "property float nx\nproperty float ny\nproperty float nz\n"
      << "property float intensity\nproperty uint views\n"
      << "element face " << m.triangles.size() << "\nproperty list uchar int vertex_indices\n"
      << "end_header\n";
  std::string bytes = out.str();
  if (ascii) {
    std::ostringstream body;
    body.precision(9);
    for (std::size_t i = 0; i < m.vertices.size(); ++i) {
      const auto& v = m.vertices[i];
      const auto& n = m.normals[i];
      body << v.x() << ' ' << v.y() << ' ' << v.z() << ' ' << n.x() << ' ' << n.y() << ' ' << n.z()
           << ' ' << m.intensity[i] << ' ' << m.views[i] << '\n';
    }
    for (const auto& t : m.triangles) {
      body << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    }
    return bytes + body.str();
  }
  const auto append = [&](const void* data, std::size_t n) {
    bytes.append(static_cast<const char*>(data), n);
  };
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    append(m.vertices[i].data(), 12);
    append(m.normals[i].data(), 12);
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
std::string stlBytes(const Mesh& m) {
  std::string bytes(80, ' ');
  bytes.replace(0, 30, "SonarCarve mesh, metres       ");
  const auto append = [&](const void* data, std::size_t n) {
    bytes.append(static_cast<const char*>(data), n);
  };
  const auto count = static_cast<std::uint32_t>(m.triangles.size());
  append(&count, 4);
  for (const auto& t : m.triangles) {
    const Eigen::Vector3f& a = m.vertices[t[0]];
    const Eigen::Vector3f normal = (m.vertices[t[1]] - a).cross(m.vertices[t[2]] - a).normalized();
    append(normal.data(), 12);
    for (std::uint32_t v : t) {
      append(m.vertices[v].data(), 12);
    }
    const std::uint16_t attribute = 0;
    append(&attribute, 2);
  }
  return bytes;
}

// Wavefront OBJ: vertices, vertex normals, and faces numbered from 1.
std::string objText(const Mesh& m) {
  std::ostringstream out;
  out.precision(9);
  out << "# SonarCarve mesh, metres\n";
  for (const auto& v : m.vertices) {
    out << "v " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
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
  const Mesh m = prepared(mesh, options);
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
  SurfacePoints kept;
  for (const SurfacePoint& p : points) {
    if (!options.crop_ned_m || options.crop_ned_m->contains(p.position_m.cast<double>())) {
      kept.push_back({toFrame(p.position_m, options), p.intensity, p.views});
    }
  }
  if (options.format == "ply") {
    writeSurfacePointsPly(kept, path);
    return;
  }
  std::ostringstream out;
  out << "ply\nformat ascii 1.0\ncomment SonarCarve points, metres\nelement vertex " << kept.size()
      << "\nproperty float x\nproperty float y\nproperty float z\nproperty float intensity\n"
         "property uint views\nend_header\n";
  out.precision(9);
  for (const auto& p : kept) {
    out << p.position_m.x() << ' ' << p.position_m.y() << ' ' << p.position_m.z() << ' '
        << p.intensity << ' ' << p.views << '\n';
  }
  writeFileAtomically(path, out.str());
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
