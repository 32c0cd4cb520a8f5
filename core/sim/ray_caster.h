// RayCaster: nearest-hit ray casting against a Scene with Embree. Building it builds the BVH
// (tens of ms for a demo scene) over its own copy of the scene; intersect() is thread safe and may
// be called from many threads at once.
#pragma once

#include <Eigen/Core>
#include <memory>

#include "geometry/scene.h"

namespace sonarcarve {

struct RayHit {
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

  const Scene& scene() const { return scene_; }

 private:
  struct Embree;
  Scene scene_;  // a copy: the caster outlives whatever it was built from
  std::unique_ptr<Embree> embree_;
};

}  // namespace sonarcarve
