// `sonarcarve-cli export RECONSTRUCTION --out FILE`: a finished reconstruction's mesh or points
// in another format, frame or crop, without recomputing anything.
#include <iostream>

#include "cli/commands.h"
#include "common/error.h"
#include "io/files/output_folder.h"
#include "io/mesh/point_cloud_ply.h"
#include "io/run/run_manifest.h"
#include "mesh/deliverable.h"
#include "pipeline/reconstruction_params.h"
#include "sonar/mission_origin.h"

namespace sonarcarve::cli {
namespace {

// The voxel size the reconstruction was carved at (its params.yaml), or the default's.
double voxelSizeOf(const std::filesystem::path& folder) {
  const auto file = folder / "params.yaml";
  return std::filesystem::exists(file)
             ? ReconstructionParams::fromYamlFile(file.string()).carve.voxel_size_m
             : ReconstructionParams().carve.voxel_size_m;
}

}  // namespace

void addExportCommand(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand(
      "export", "Convert a reconstruction's mesh or points to another format, frame or crop");
  struct Options {
    std::string reconstruction, out, format, frame = "ned", crs;
    std::vector<double> origin, crop;
    double cell_m = 0.25;
    bool points = false;
    bool add_origin = false;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("reconstruction", o->reconstruction, "Folder written by reconstruct")->required();
  cmd->add_option("--out", o->out, "File to write (.ply, .stl, .obj, .las, .tif)")->required();
  cmd->add_option("--format", o->format,
                  "ply | ply-ascii | stl | obj | las | geotiff (default: from --out)");
  cmd->add_option("--frame", o->frame,
                  "ned (as inside) | zup (x east, y north, z up, for CAD tools)")
      ->capture_default_str();
  cmd->add_option("--origin", o->origin, "Origin subtracted first: N E D (m)")->expected(3);
  cmd->add_option("--crop", o->crop, "Keep only inside the box N0 E0 D0 N1 E1 D1 (m, NED)")
      ->expected(6);
  cmd->add_option("--crs", o->crs,
                  "World coordinates in this projected CRS (EPSG:NNNN or a PROJ string): x "
                  "easting, y northing, z up, in double (PLY, OBJ, LAS; not STL); needs a "
                  "reconstruction with a CRS (its PLY comment crs)");
  cmd->add_option("--cell", o->cell_m,
                  "geotiff: edge of the seabed grid's cells, m (the grid: docs/formats.md, "
                  "\"Seabed elevation (GeoTIFF)\")")
      ->capture_default_str()
      ->check(CLI::Range(SeabedGridParams::kCell.min, SeabedGridParams::kCell.max));
  cmd->add_flag("--points", o->points,
                "Export the surface points instead of the mesh (PLY; LAS always holds "
                "the points: x east, y north, z up, in the mission's CRS when it has one)");
  cmd->add_flag("--add-origin", o->add_origin,
                "World coordinates: add back the mission origin the reconstruction is local to "
                "(its PLY comment origin_ned_m), in double (PLY double, OBJ 6 decimals; not STL)");
  cmd->callback([o, &exit_code] {
    // The target is checked, and its folder held, before anything is read.
    const auto hold = holdOutputFile(o->out);
    DeliverableRequest request;
    request.points = o->points;
    request.cell_m = o->cell_m;
    ExportOptions& options = request.options;
    options.format = o->format.empty() ? formatOfPath(o->out) : o->format;
    options.frame = o->frame;
    if (!o->origin.empty()) {
      options.origin_ned_m = Eigen::Vector3d(o->origin[0], o->origin[1], o->origin[2]);
    }
    if (!o->crop.empty()) {
      options.crop_ned_m = Eigen::AlignedBox3d(Eigen::Vector3d(o->crop[0], o->crop[1], o->crop[2]),
                                               Eigen::Vector3d(o->crop[3], o->crop[4], o->crop[5]));
    }
    const std::filesystem::path folder(o->reconstruction);
    // A run that failed or never ended has left files of its own and none of an earlier run
    // (io/run/run_manifest.h): exporting them would pass a partial result for a deliverable.
    const std::optional<std::string> status = manifestStatus(folder);
    if (status && *status != "complete" && *status != "cancelled") {
      throw Error((folder / RunManifest::kFileName).string(), "status",
                  "the run that wrote this folder is '" + *status +
                      "': expected a complete run (run reconstruct again)");
    }
    if (status && *status == "cancelled") {
      std::cerr << "warning: the run that wrote " << folder.string()
                << " was cancelled: its map holds the frames carved before\n";
    }
    const bool points = madeFromPoints(request);
    const std::filesystem::path input = folder / (points ? "surface_points.ply" : "mesh.ply");
    options.mission_origin_ned_m = plyOrigin(input);
    options.add_mission_origin = o->add_origin;
    options.mission_crs = plyCrs(input);
    options.target_crs = o->crs;
    DeliverableSource source;
    SurfacePoints surface;
    Mesh mesh;
    if (points) {
      surface = readSurfacePointsPly(input);
      source.points = &surface;
      source.voxel_size_m = voxelSizeOf(folder);
    } else {
      mesh = readMeshPly(input);
      source.mesh = &mesh;
    }
    writeDeliverable(request, source, o->out);
    std::cout << "wrote " << o->out << " (" << deliverableSummary(request) << ")\n";
    exit_code = 0;
  });
}

}  // namespace sonarcarve::cli
