// RayCaster: nearest-hit ray casting against a Scene with Embree. Building it builds the BVH
// (tens of ms for a demo scene) over its own copy of the scene; intersect() and intersectFan()
// are thread safe and may be called from many threads at once.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <span>

#include "geometry/scene.h"

namespace sonarcarve {

struct RayHit {
  bool found = false;      ///< false: nothing within the ray's reach (the rest is unset)
  float distance = 0.0f;   ///< along the unit direction, metres
  Eigen::Vector3f normal;  ///< smooth-shading unit normal at the hit (either side)
  std::uint32_t triangle = 0;
};

class RayCaster {
 public:
  /// Throws Error if the scene has no triangles or Embree cannot start.
  explicit RayCaster(const Scene& scene);
  ~RayCaster();
  RayCaster(const RayCaster&) = delete;
  RayCaster& operator=(const RayCaster&) = delete;

  /// The first surface along origin + t * direction (unit), for t in (0, max_distance].
  bool intersect(const Eigen::Vector3f& origin, const Eigen::Vector3f& direction,
                 float max_distance, RayHit& hit) const;
  /// The first surface along each of the rays from one origin, origin + t * directions[i] for t
  /// in (0, max_distance], into hits[i] (same size). Traced as Embree packets of 16 rays in the
  /// order given, several times faster than one at a time when neighbours point alike (the
  /// elevations of one beam); hits equal intersect()'s up to float rounding.
  void intersectFan(const Eigen::Vector3f& origin, std::span<const Eigen::Vector3f> directions,
                    float max_distance, std::span<RayHit> hits) const;

  const Scene& scene() const { return scene_; }

 private:
  struct Embree;
  void fillHit(unsigned triangle, float u, float v, float distance, RayHit& hit) const;
  Scene scene_;  // a copy: the caster outlives whatever it was built from
  std::unique_ptr<Embree> embree_;
};

}  // namespace sonarcarve
