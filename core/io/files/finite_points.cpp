#include "io/files/finite_points.h"

#include <sstream>

#include "common/error.h"

namespace sonarcarve {

void requireFinitePoint(const Eigen::Vector3f& p, const std::string& source,
                        const std::string& place) {
  if (p.allFinite()) {
    return;
  }
  std::ostringstream found;
  found << p.x() << ", " << p.y() << ", " << p.z();
  throw Error(source, place, "expected finite coordinates, found (" + found.str() + ")");
}

}  // namespace sonarcarve
