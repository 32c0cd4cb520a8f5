// A transform between two CRSs by PROJ (proj_create_crs_to_crs), with the axes in the order of
// visualisation whatever the authority says (proj_normalize_for_visualization): longitude then
// latitude in degrees, easting then northing in metres, then height. One object serves one
// thread at a time (it owns its PROJ context).
#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>

namespace sonarcarve {

class CrsTransform {
 public:
  /// Throws Error(source, place, ...) naming the CRS PROJ does not know, or that no operation
  /// joins them. `source` and `place` say where the CRSs came from ("mission.yaml", "crs").
  CrsTransform(const std::string& from_crs, const std::string& to_crs, const std::string& source,
               const std::string& place);
  ~CrsTransform();
  CrsTransform(CrsTransform&&) noexcept;
  CrsTransform& operator=(CrsTransform&&) noexcept;

  /// (x, y, z) in the first CRS, in the same order in the second; nothing where PROJ cannot
  /// (a point outside the projection's domain): lastError() says why.
  std::optional<Eigen::Vector3d> apply(const Eigen::Vector3d& xyz) const;
  std::string lastError() const;

 private:
  struct Handles;
  std::unique_ptr<Handles> handles_;
};

}  // namespace sonarcarve
