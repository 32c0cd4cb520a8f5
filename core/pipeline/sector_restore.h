// Sector restore: the surface that each heading's own carve keeps and the mission's map carved
// away, put back where no view that would have seen it brightly carved it. A view carves a
// voxel where its pixel bounds a return there under the keep level (carve/carve_params.h); a
// face seen at grazing incidence returns little into any one range bin (its echo spreads over
// the ranges its length covers, and Lambert's law weakens it), so views from other headings
// carve faces that one heading sees head-on: on a jacket node seen from four descents the views
// that carved away visible surface saw it 50 to 90 degrees off its normal, almost never less.
//
// Each sector (pipeline/heading_sectors.h) is carved alone; a voxel of its surface (where the
// sector swept its elevation beam over it: elevationSwept) that the
// mission's map carved is set back to the sector's value unless another sector carved it too
// while looking at it within kTrustedIncidence of the surface's normal there (the normal from
// the sector's surface around it). A ghost of one sector (a return placed at the wrong
// elevation) is carved by the other sectors that see its place head-on.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "carve/voxel_map.h"
#include "occlusion/surface_points.h"
#include "pipeline/frame_stage.h"
#include "sonar/sonar_model.h"

namespace sonarcarve {

/// A sector's carve trusted to remove another sector's surface when it looks at it within this
/// angle of the surface's normal, radians (45 degrees).
inline constexpr double kTrustedIncidence = 0.7853981633974483;
/// A sector's surface is set back where its views' elevations to it span at least this share of
/// the vertical aperture (at half of it, level orbits set back their ghosts:
/// docs/design/heading-sectors.md).
inline constexpr double kSweptApertureShare = 1.0;

/// One heading sector carved alone.
struct SectorCarve {
  const VoxelMap* map = nullptr;                     ///< on the mission map's grid
  SurfacePoints surface;                             ///< its resolved surface
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< its sonars' mean position
};

struct SectorRestoreCount {
  std::size_t candidates = 0;  ///< the sectors' surface voxels
  std::size_t restored = 0;    ///< voxels the mission's map had carved, set back
  std::size_t vetoed = 0;      ///< carved by a sector that looked at them nearly head-on
  std::size_t no_normal = 0;   ///< too few surface neighbours to tell a normal
};

/// Sets back into `mission_map` the voxels of the sectors' surfaces that it carved, with their
/// sector's value (the smallest of the sectors'), unless another sector carved the voxel while
/// looking at it (from its sonars' mean position) within `trusted_incidence_rad` of the
/// surface's normal, with no sector's surface between them (which may have hidden it).
SectorRestoreCount restoreSectorSurfaces(VoxelMap& mission_map,
                                         const std::vector<SectorCarve>& sectors,
                                         double trusted_incidence_rad = kTrustedIncidence);

/// Whether `frames` swept their elevation beam over each point: the point lies in the fan of
/// views whose elevations to it span at least `min_span_rad` within the beam's main lobe (to its
/// reach). A
/// sector that holds its sonar at one height and tilt around a structure (a level orbit) sees
/// each point at one elevation and cannot tell it from the other points of its arc: its surface
/// there may be ghosts, and is not set back.
std::vector<bool> elevationSwept(const SurfacePoints& points, const std::vector<PosedFrame>& frames,
                                 const SonarModel& sonar, double min_span_rad);

/// The unit normal of a surface at each of its voxels: the direction of least spread of the
/// surface voxels within 2 voxels of it; zero where fewer than 6 lie there.
std::vector<Eigen::Vector3f> surfaceNormals(const std::vector<Eigen::Vector3i>& voxels);

}  // namespace sonarcarve
