// Voxelised solids for the forward model's tests (model/block_grid.h): a grid whose logits
// follow a solid's signed distance, nearly 1 inside and nearly 0 outside.
#pragma once

#include <Eigen/Geometry>
#include <functional>

#include "model/block_grid.h"

namespace sonarcarve::test {

/// Signed distance to a solid's surface (metres, negative inside), world frame.
using SignedDistance = std::function<double(const Eigen::Vector3d&)>;

/// Sets the voxels of `box` within `band` voxels of the surface: logit = -sd / size * slope,
/// clamped to [grid's empty logit, 6] (alpha 0.998 inside, as good as 0 outside), reflectance
/// `reflectance`. Voxels already set keep the
/// larger logit (solids unite).
void voxelise(BlockGrid& grid, const SignedDistance& sd, const Eigen::AlignedBox3d& box,
              double band, double slope, float reflectance);

/// A slab between two parallel planes: `centre` on its front face, `normal` out of it.
SignedDistance slab(const Eigen::Vector3d& centre, const Eigen::Vector3d& normal, double thickness);
/// An infinite cylinder of `radius` around the line through `point` along `axis`.
SignedDistance cylinder(const Eigen::Vector3d& point, const Eigen::Vector3d& axis, double radius);

}  // namespace sonarcarve::test
