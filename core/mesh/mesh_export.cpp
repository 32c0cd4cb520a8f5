#include "mesh/mesh_export.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iomanip>
#include <sstream>

#include "common/error.h"
#include "common/number_text.h"
#include "common/progress.h"
#include "geo/crs.h"
#include "geo/crs_transform.h"
#include "io/files/atomic_file.h"
#include "io/mesh/las_file.h"
#include "io/mesh/ply_check.h"
#include "io/mesh/point_cloud_ply.h"
#include "io/raster/geotiff_file.h"
#include "mesh/seabed_grid.h"
#include "sonar/mission_origin.h"

namespace sonarcarve {
namespace {

// World coordinates out: the mission origin added back (and, for a target CRS, projected).
bool worldOutput(const ExportOptions& o) {
  return o.add_mission_origin || !o.target_crs.empty();
}

// What is added to a local position before the frame: the mission origin, for world output.
Eigen::Vector3d addedOrigin(const ExportOptions& o) {
  return worldOutput(o) ? o.mission_origin_ned_m : Eigen::Vector3d::Zero();
}

// Local positions and directions to the output frame: NED or Z-up, local or world, or world
// in a target CRS through PROJ.
class OutputFrame {
 public:
  explicit OutputFrame(const ExportOptions& o) : o_(o) {
    if (!o.target_crs.empty()) {
      to_target_.emplace(o.mission_crs, o.target_crs, "export", "crs");
    }
  }

  // In double. Zero offsets are not added, so that a local export keeps every float to the
  // bit (a -0 stays -0).
  Eigen::Vector3d position(const Eigen::Vector3f& p_local) const {
    Eigen::Vector3d q = p_local.cast<double>();
    if (worldOutput(o_) && !o_.mission_origin_ned_m.isZero()) {
      q += o_.mission_origin_ned_m;
    }
    if (to_target_) {
      return projected(q);
    }
    if (!o_.origin_ned_m.isZero()) {
      q -= o_.origin_ned_m;
    }
    return o_.frame == "zup" ? Eigen::Vector3d(q.y(), q.x(), -q.z()) : q;
  }

  // Easting, northing and up of the target CRS's axes, as zup: the grids' convergence between
  // the mission's CRS and the target's (a fraction of a degree) is not applied to normals.
  Eigen::Vector3f direction(const Eigen::Vector3f& d_ned) const {
    return o_.frame == "zup" || to_target_ ? Eigen::Vector3f(d_ned.y(), d_ned.x(), -d_ned.z())
                                           : d_ned;
  }

 private:
  // World NED on the mission's grid to (easting, northing, up) in the target CRS.
  Eigen::Vector3d projected(const Eigen::Vector3d& q_world) const {
    const auto xy = to_target_->apply({q_world.y(), q_world.x(), 0.0});
    if (!xy) {
      throw Error("export", "crs",
                  "PROJ cannot place the world point " + nedText(q_world) + " of " +
                      o_.mission_crs + " in " + o_.target_crs + " (" + to_target_->lastError() +
                      "): expected a target CRS whose area holds the map");
    }
    return {xy->x(), xy->y(), -q_world.z()};
  }

  const ExportOptions& o_;
  std::optional<CrsTransform> to_target_;
};

// Reports the export's steps and stops it when asked (every kStepReport items: PROJ places a
// few hundred thousand points a second).
class ExportSteps {
 public:
  static constexpr std::size_t kStepReport = 16384;
  ExportSteps(Progress* progress, std::size_t total) : progress_(progress), total_(total) {}
  void at(std::size_t done) const {
    if (progress_ && done % kStepReport == 0) {
      check();
      progress_->report("export", done, total_);
    }
  }
  void check() const {
    if (progress_ && progress_->cancelled()) {
      throw Cancelled();
    }
  }

 private:
  Progress* progress_;
  std::size_t total_;
};

bool insideCrop(const Eigen::Vector3f& p_local, const ExportOptions& o) {
  return !o.crop_ned_m || o.crop_ned_m->contains(p_local.cast<double>() + addedOrigin(o));
}

// The origin to add back to what the file holds to get world NED (its PLY comment), or zero.
Eigen::Vector3d fileOrigin(const ExportOptions& o) {
  return (worldOutput(o) ? Eigen::Vector3d::Zero() : o.mission_origin_ned_m) + o.origin_ned_m;
}

// The header comments after the origin's: the CRS of what the file holds, and for a target
// CRS its axes and the mission origin (which the coordinates are not local to).
std::vector<std::string> placeComments(const ExportOptions& o) {
  if (o.target_crs.empty()) {
    return o.mission_crs.empty() ? std::vector<std::string>{}
                                 : std::vector<std::string>{crsComment(o.mission_crs)};
  }
  return {crsComment(o.target_crs),
          "axes x easting, y northing, z up (= -depth), metres, in that crs",
          "mission origin (north east down) " + nedText(o.mission_origin_ned_m) +
              " on the grid of " + o.mission_crs + "; these coordinates are not local to it"};
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
  std::vector<std::string> place_comments;  ///< CRS, axes
};

Prepared preparedFor(const ExportOptions& o, const char* kind) {
  Prepared out;
  out.world_double = worldOutput(o);
  out.kind = kind;
  out.origin_comment = fileOrigin(o);
  out.place_comments = placeComments(o);
  return out;
}

// The mesh in the output frame, cropped; vertices no triangle uses are dropped.
Prepared prepared(const Mesh& mesh, const ExportOptions& o, Progress* progress) {
  Prepared out = preparedFor(o, "mesh");
  const OutputFrame frame(o);
  const ExportSteps steps(progress, mesh.triangles.size());
  std::vector<std::int64_t> remap(mesh.vertices.size(), -1);
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    steps.at(i);
    const auto& t = mesh.triangles[i];
    if (!insideCrop(mesh.vertices[t[0]], o) || !insideCrop(mesh.vertices[t[1]], o) ||
        !insideCrop(mesh.vertices[t[2]], o)) {
      continue;
    }
    std::array<std::uint32_t, 3> nt{};
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = t[static_cast<std::size_t>(k)];
      if (remap[v] < 0) {
        remap[v] = static_cast<std::int64_t>(out.positions.size());
        out.positions.push_back(frame.position(mesh.vertices[v]));
        out.normals.push_back(frame.direction(mesh.normals[v]));
        out.intensity.push_back(mesh.intensity[v]);
        out.views.push_back(mesh.views[v]);
      }
      nt[static_cast<std::size_t>(k)] = static_cast<std::uint32_t>(remap[v]);
    }
    out.triangles.push_back(nt);
  }
  return out;
}

Prepared prepared(const SurfacePoints& points, const ExportOptions& o, Progress* progress) {
  Prepared out = preparedFor(o, "points");
  const OutputFrame frame(o);
  const ExportSteps steps(progress, points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    steps.at(i);
    const SurfacePoint& p = points[i];
    if (insideCrop(p.position_m, o)) {
      out.positions.push_back(frame.position(p.position_m));
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
  for (const std::string& comment : m.place_comments) {
    out << "comment " << comment << "\n";
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
  for (const std::string& comment : m.place_comments) {
    out << "# " << comment << "\n";
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

// A target CRS: a projected one in metres, a mission with a CRS to project from, a format
// that holds double, world coordinates as they are (no frame, origin or added origin of ours).
void validateTarget(const ExportOptions& o) {
  if (const auto problem = gridCrsProblem(o.target_crs)) {
    throw Error("export", "crs", *problem);
  }
  if (o.mission_crs.empty()) {
    throw Error("export", "crs",
                "the reconstruction has no CRS (its navigation was NED without one): expected a "
                "mission with latitude/longitude navigation or crs: in its mission.yaml");
  }
  if (o.format == "stl") {
    throw Error("export", "format stl",
                "STL holds float32 coordinates, which keep only metres at a CRS's eastings and "
                "northings: expected ply, ply-ascii or obj with a crs");
  }
  if (o.frame != "ned" || !o.origin_ned_m.isZero() || o.add_mission_origin) {
    throw Error("export", "crs",
                "a CRS's coordinates are easting, northing, up as they are: expected no frame, "
                "origin or add-origin with it");
  }
}

// LAS and GeoTIFF hold x east, y north, z up: in the target CRS, else in the mission's CRS
// (its world coordinates are that CRS's), else local (or world with add-origin) NED turned to
// Z-up with no CRS.
ExportOptions zUpOptions(const ExportOptions& o) {
  ExportOptions las = o;
  if (las.target_crs.empty() && !las.mission_crs.empty() && las.origin_ned_m.isZero()) {
    las.target_crs = las.mission_crs;
    las.add_mission_origin = false;
  }
  if (las.target_crs.empty()) {
    las.frame = "zup";
  }
  return las;
}

// The points to export, or an Error naming `path` when none is left (an empty reconstruction,
// or a crop box that holds none): a file of no point is no export, as a mesh of no triangle.
// (LAS and GeoTIFF exports of an empty crop box were written, with exit 0.)
Prepared requirePoints(Prepared m, const std::filesystem::path& path) {
  if (m.positions.empty()) {
    throw Error(path.string(), "", "no point to export (empty reconstruction or crop box)");
  }
  return m;
}

std::string lasFileBytes(const SurfacePoints& points, const std::filesystem::path& path,
                         const ExportOptions& o, Progress* progress) {
  const Prepared m = requirePoints(prepared(points, o, progress), path);
  LasCloud cloud;
  if (!o.target_crs.empty()) {
    cloud.crs_wkt = crsWkt(o.target_crs, "export", "crs");
  }
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    LasPoint p;
    p.xyz = m.positions[i];
    p.intensity =
        static_cast<std::uint16_t>(std::clamp(std::round(m.intensity[i]), 0.0f, 65535.0f));
    p.user_data = static_cast<std::uint8_t>(std::min<std::uint32_t>(m.views[i], 255));
    cloud.points.push_back(p);
  }
  return lasBytes(cloud, path.string());
}

// "1e+300 0 nan": a point as given, for a message.
std::string numbersText(const Eigen::Vector3d& p) {
  return shortestNumber(p.x()) + " " + shortestNumber(p.y()) + " " + shortestNumber(p.z());
}

}  // namespace

void ExportOptions::validate() const {
  if (format != "ply" && format != "ply-ascii" && format != "stl" && format != "obj" &&
      format != "las" && format != "geotiff") {
    throw Error("export", "format", "expected ply, ply-ascii, stl, obj, las or geotiff");
  }
  if (frame != "ned" && frame != "zup") {
    throw Error("export", "frame", "expected ned or zup");
  }
  // Beyond where any survey lies (kMaxNavCoordinate_m), an origin turned float32 coordinates
  // into infinities, written with exit 0.
  for (const Eigen::Vector3d& origin : {mission_origin_ned_m, origin_ned_m}) {
    if (!origin.allFinite() || origin.cwiseAbs().maxCoeff() > kMaxNavCoordinate_m) {
      throw Error(
          "export", "origin",
          "expected finite origins within 1e8 m of zero (metres, NED), got " + numbersText(origin));
    }
  }
  if (crop_ned_m && !(crop_ned_m->min().allFinite() && crop_ned_m->max().allFinite() &&
                      (crop_ned_m->min().array() <= crop_ned_m->max().array()).all())) {
    throw Error("export", "crop",
                "expected a box N0 E0 D0 N1 E1 D1 of finite numbers, each of N0, E0, D0 at most "
                "N1, E1, D1 (metres, NED), got " +
                    numbersText(crop_ned_m->min()) + " to " + numbersText(crop_ned_m->max()));
  }
  if (!target_crs.empty()) {
    validateTarget(*this);
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
  if (ext == ".ply" || ext == ".stl" || ext == ".obj" || ext == ".las") {
    return ext.substr(1);
  }
  if (ext == ".tif" || ext == ".tiff") {
    return "geotiff";
  }
  throw Error(path.string(), "", "unknown file type: expected .ply, .stl, .obj, .las or .tif");
}

void exportMesh(const Mesh& mesh, const std::filesystem::path& path, const ExportOptions& options,
                Progress* progress) {
  options.validate();
  if (options.format == "las" || options.format == "geotiff") {
    throw Error(path.string(), "",
                options.format + " is made from points: expected the surface points (--points)");
  }
  const Prepared m = prepared(mesh, options, progress);
  if (m.triangles.empty()) {
    throw Error(path.string(), "", "no triangle to export (empty mesh or crop box)");
  }
  ExportSteps(progress, 0).check();
  if (options.format == "stl") {
    writeFileAtomically(path, stlBytes(m));
  } else if (options.format == "obj") {
    writeFileAtomically(path, objText(m));
  } else {
    writeFileAtomically(path, plyText(m, options.format == "ply-ascii"));
  }
}

void exportPoints(const SurfacePoints& points, const std::filesystem::path& path,
                  const ExportOptions& options, Progress* progress) {
  options.validate();
  std::string bytes;
  if (options.format == "las") {
    const ExportOptions las = zUpOptions(options);
    las.validate();
    bytes = lasFileBytes(points, path, las, progress);
  } else if (options.format == "ply" || options.format == "ply-ascii") {
    bytes = plyText(requirePoints(prepared(points, options, progress), path),
                    options.format == "ply-ascii");
  } else {
    throw Error(path.string(), "", "points are exported as PLY or LAS only");
  }
  ExportSteps(progress, 0).check();
  writeFileAtomically(path, bytes);
}

void exportSeabedGrid(const SurfacePoints& points, const std::filesystem::path& path,
                      const ExportOptions& options, const SeabedGridParams& grid,
                      Progress* progress) {
  options.validate();
  const ExportOptions o = zUpOptions(options);
  o.validate();
  HeightRaster raster =
      seabedGrid(requirePoints(prepared(points, o, progress), path).positions, grid);
  ExportSteps(progress, 0).check();
  if (!o.target_crs.empty()) {
    raster.crs_wkt = crsWkt(o.target_crs, "export", "crs");
  }
  raster.description =
      "seabed height, up (= -depth), metres: per cell the median of the points "
      "within " +
      shortestNumber(grid.band_m()) + " m above its lowest surface";
  writeGeoTiff(path, raster);
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
