#include "io/mesh/obj_mesh.h"

#include <charconv>
#include <sstream>
#include <string>

#include "common/error.h"
#include "common/input_limits.h"
#include "io/files/finite_points.h"
#include "io/files/input_file.h"

namespace sonarcarve {
namespace {

template <typename Number>
bool parse(const std::string& word, Number& value) {
  const char* end = word.data() + word.size();
  const auto [ptr, ec] = std::from_chars(word.data(), end, value);
  return ec == std::errc() && ptr == end;
}

struct Face {
  int line = 0;
  std::vector<long long> corners;  ///< as written: from 1, or negative from the end
};

// A corner's index into `vertices` vertices (0-based) as written, or -1 if it names none.
long long resolved(long long written, std::size_t vertices) {
  const auto n = static_cast<long long>(vertices);
  const long long index = written > 0 ? written - 1 : n + written;
  return written != 0 && index >= 0 && index < n ? index : -1;
}

}  // namespace

ObjMesh readObjMesh(const std::filesystem::path& path, const Eigen::Vector3d& origin_ned_m) {
  const std::string file = path.string();
  std::istringstream text(
      std::string(withoutByteOrderMark(readInputFile(path, "an OBJ mesh", kMaxMeshFileBytes))));
  ObjMesh mesh;
  std::vector<Face> faces;
  int line_number = 0;
  for (std::string line; std::getline(text, line);) {
    ++line_number;
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "v") {
      std::string x, y, z;
      Eigen::Vector3d world;
      if (!(words >> x >> y >> z) || !parse(x, world.x()) || !parse(y, world.y()) ||
          !parse(z, world.z())) {
        throw Error(file, linePlace(line_number), "expected 'v X Y Z' with three numbers");
      }
      const Eigen::Vector3f p = (world - origin_ned_m).cast<float>();
      requireFinitePoint(p, file, linePlace(line_number));
      mesh.vertices.push_back(p);
    } else if (keyword == "f") {
      Face face{line_number, {}};
      for (std::string corner; words >> corner;) {
        long long index = 0;
        if (!parse(corner.substr(0, corner.find('/')), index)) {
          throw Error(file, linePlace(line_number),
                      "expected vertex indices, found '" + corner + "'");
        }
        face.corners.push_back(index);
      }
      if (face.corners.size() < 3) {
        throw Error(file, linePlace(line_number), "expected at least 3 vertex indices");
      }
      faces.push_back(std::move(face));
    }
  }
  for (const Face& face : faces) {
    std::vector<std::uint32_t> corners;
    for (const long long written : face.corners) {
      const long long index = resolved(written, mesh.vertices.size());
      if (index < 0) {
        throw Error(file, linePlace(face.line),
                    "vertex index " + std::to_string(written) + " out of range: expected 1 to " +
                        std::to_string(mesh.vertices.size()) + " (or -1 to -" +
                        std::to_string(mesh.vertices.size()) + ")");
      }
      corners.push_back(static_cast<std::uint32_t>(index));
    }
    for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
      mesh.triangles.push_back({corners[0], corners[k], corners[k + 1]});
    }
  }
  return mesh;
}

}  // namespace sonarcarve
