// A deliverable of a finished reconstruction, as `sonarcarve-cli export` and the workbench's
// export dialog both write it: the run's product it is made from (the mesh; the surface points
// for --points, LAS and GeoTIFF), the mesh_export.h function that writes it, and the words
// that say what the file holds. The callers differ only in where the products come from (a
// reconstruction folder's PLYs, the workbench's last run).
#pragma once

#include <filesystem>
#include <string>

#include "mesh/mesh_export.h"

namespace sonarcarve {

struct DeliverableRequest {
  ExportOptions options;  ///< format, frame, origins, crop, CRSs
  bool points = false;    ///< the surface points rather than the mesh (ply, ply-ascii)
  double cell_m = 0.25;   ///< geotiff: the edge of the seabed grid's cells, metres
};

/// The run's products a deliverable is made from; the one it needs (madeFromPoints) is given.
struct DeliverableSource {
  const Mesh* mesh = nullptr;
  const SurfacePoints* points = nullptr;
  double voxel_size_m = 0.02;  ///< geotiff: the voxel the surface was carved at
};

/// True when the deliverable is made from the surface points (--points, las, geotiff).
bool madeFromPoints(const DeliverableRequest& request);

/// Writes the deliverable to `path` (mesh_export.h: validated first, written atomically).
/// Throws Error when the product it needs is missing or the options are refused, Cancelled
/// when `progress` is cancelled (nothing written).
void writeDeliverable(const DeliverableRequest& request, const DeliverableSource& source,
                      const std::filesystem::path& path, Progress* progress = nullptr);

/// What the file holds, for the line after it is written: "las, x east, y north, z up, world
/// coordinates in EPSG:32631", "ply, ned frame, local to the origin N 0 E 0 D 0".
std::string deliverableSummary(const DeliverableRequest& request);

}  // namespace sonarcarve
