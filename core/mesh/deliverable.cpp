#include "mesh/deliverable.h"

#include "common/error.h"
#include "sonar/mission_origin.h"

namespace sonarcarve {
namespace {

// LAS and GeoTIFF hold x east, y north, z up whatever the frame (mesh_export.h).
bool zUpFormat(const std::string& format) {
  return format == "las" || format == "geotiff";
}

}  // namespace

bool madeFromPoints(const DeliverableRequest& request) {
  return request.points || zUpFormat(request.options.format);
}

void writeDeliverable(const DeliverableRequest& request, const DeliverableSource& source,
                      const std::filesystem::path& path, Progress* progress) {
  const ExportOptions& options = request.options;
  if (!madeFromPoints(request)) {
    if (!source.mesh || source.mesh->triangles.empty()) {
      throw Error(
          path.string(), "",
          "the run made no mesh: expected a run with the mesh on (Build a mesh), or points");
    }
    exportMesh(*source.mesh, path, options, progress);
    return;
  }
  if (!source.points || source.points->empty()) {
    throw Error(path.string(), "", "the run kept no surface points to export");
  }
  if (options.format == "geotiff") {
    SeabedGridParams grid;
    grid.cell_m = request.cell_m;
    grid.voxel_size_m = source.voxel_size_m;
    exportSeabedGrid(*source.points, path, options, grid, progress);
  } else {
    exportPoints(*source.points, path, options, progress);
  }
}

std::string deliverableSummary(const DeliverableRequest& request) {
  const ExportOptions& o = request.options;
  const bool z_up = zUpFormat(o.format);
  // LAS and GeoTIFF are in the mission's CRS unless an origin of ours is subtracted.
  const std::string crs = !o.target_crs.empty()             ? o.target_crs
                          : z_up && o.origin_ned_m.isZero() ? o.mission_crs
                                                            : "";
  return o.format + ", " + (z_up ? std::string("x east, y north, z up") : o.frame + " frame") +
         ", " +
         (!crs.empty()           ? "world coordinates in " + crs
          : o.add_mission_origin ? "world coordinates"
                                 : "local to the origin " + nedText(o.mission_origin_ned_m));
}

}  // namespace sonarcarve
