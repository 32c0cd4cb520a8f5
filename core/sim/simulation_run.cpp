#include "sim/simulation_run.h"

#include <cmath>
#include <sstream>

#include "common/angles.h"
#include "common/error.h"
#include "common/serial_worker.h"
#include "geometry/scene_io.h"
#include "io/files/atomic_file.h"
#include "io/files/yaml_fields.h"
#include "io/mission/mission_writer.h"
#include "io/mission/nav_csv.h"
#include "sim/frame_renderer.h"
#include "sim/visible_surface.h"

namespace sonarcarve {
namespace {

std::string settingsYaml(const SimulationRequest& r, const std::optional<SeabedFieldSpec>& f,
                         const SeabedReliefSpec& relief, std::size_t frames,
                         double traced_elevation_rad, ElevationBeam declared) {
  std::ostringstream out;
  const auto& t = r.trajectory;
  out << "# Settings this mission was simulated with (sonarcarve-cli simulate).\n"
      << "scene: " << r.scene_source << "\n"
      << "empty_water: " << (r.empty_water ? "true" : "false") << "\n"
      << "frames: " << frames << "\n"
      << "trajectory:\n"
      << "  kind: " << t.kind << "\n"
      << "  standoff_m: " << shortestNumber(t.standoff_m) << "\n"
      << "  step_m: " << shortestNumber(t.step_m) << "\n"
      << "  speed_mps: " << shortestNumber(t.speed_mps) << "\n"
      << "  altitude_m: " << shortestNumber(t.altitude_m) << "\n"
      << "  line_spacing_m: " << shortestNumber(t.line_spacing_m) << "\n"
      << "  tilt_deg: " << shortestNumber(t.tilt_deg) << "\n"
      << "  line_length_m: " << shortestNumber(t.line_length_m) << "\n"
      << "  survey_width_m: " << shortestNumber(t.survey_width_m) << "\n"
      << "  laps: " << shortestNumber(t.laps) << "\n"
      << "  frames: " << t.frames << "\n"
      << "  orbit_levels: " << t.orbit_levels << "\n"
      << "  level_spacing_m: " << shortestNumber(t.level_spacing_m) << "\n"
      << "  descents: " << t.descents << "\n"
      << "  view_tilt_deg: " << shortestNumber(t.view_tilt_deg) << "\n";
  if (f) {
    out << "field:\n"
        << "  seed: " << f->seed << "\n"
        << "  depth_m: " << shortestNumber(f->depth_m) << "\n"
        << "  relief_m: " << shortestNumber(f->relief_m) << "\n"
        << "  tile_m: " << shortestNumber(f->tile_m) << "\n"
        << "  grid_m: " << shortestNumber(f->grid_m) << "\n"
        << "  max_objects_per_tile: " << f->max_objects_per_tile << "\n";
  }
  if (relief.relief_m > 0.0) {
    out << "seabed_relief:\n"
        << "  relief_m: " << shortestNumber(relief.relief_m) << "\n"
        << "  wavelength_m: " << shortestNumber(relief.wavelength_m) << "\n"
        << "  seed: " << relief.seed << "\n";
  }
  out << "imaging:\n"
      << "  elevation_step_deg: " << shortestDegrees(r.imaging.elevation_step_rad) << "\n"
      << "  rays_per_beam: " << r.imaging.rays_per_beam << "\n"
      << "  gain: " << shortestNumber(r.imaging.gain) << "\n"
      << "  spreading_exponent: " << shortestNumber(r.imaging.spreading_exponent) << "\n"
      << "  tvg_exponent: " << shortestNumber(r.imaging.tvg_exponent) << "\n"
      << "  beam: " << beamName(r.imaging.beam) << "\n"
      << "  elevation_beam: " << elevationFamilyName(r.imaging.elevation_beam.family) << "\n";
  if (r.imaging.elevation_beam.table) {
    YAML::Emitter file;
    file << YAML::DoubleQuoted << r.imaging.elevation_beam.table->file;
    out << "  elevation_beam_table: " << file.c_str() << "\n";
  }
  out << "  declared_beam: " << elevationBeamName(declared) << "\n"
      << "  traced_elevation_deg: " << shortestDegrees(traced_elevation_rad) << "\n"
      << "  side_lobes: " << r.imaging.side_lobes << "\n"
      << "  horizontal_beam_width_deg: " << shortestDegrees(r.imaging.horizontal_beam_width_rad)
      << "\n"
      << "  visible_beam_level_db: " << shortestNumber(r.imaging.visible_beam_level_db) << "\n"
      << "  visible_cell_m: " << shortestNumber(r.imaging.visible_cell_m) << "\n"
      << "navigation_error:\n"
      << "  position_sigma_m: " << shortestNumber(r.nav_error.position_sigma_m) << "\n"
      << "  attitude_sigma_deg: " << shortestNumber(r.nav_error.attitude_sigma_deg) << "\n"
      << "  position_bias_m: " << shortestNumber(r.nav_error.position_bias_m) << "\n"
      << "  attitude_bias_deg: " << shortestNumber(r.nav_error.attitude_bias_deg) << "\n"
      << "  position_noise_m: " << shortestNumber(r.nav_error.position_noise_m) << "\n"
      << "  attitude_noise_deg: " << shortestNumber(r.nav_error.attitude_noise_deg) << "\n"
      << "  axes: " << navAxesNames(r.nav_error.axes) << "\n"
      << "  seed: " << r.nav_error.seed << "\n"
      << "noise:\n";
  std::istringstream noise(r.noise.toYaml());
  for (std::string line; std::getline(noise, line);) {
    out << "  " << line << "\n";
  }
  return out.str();
}

// The north-east box the sonar can reach from the first `frames` poses.
Eigen::AlignedBox2d reachOf(const Trajectory& trajectory, std::size_t frames,
                            const SonarModel& sonar) {
  Eigen::AlignedBox2d box;
  for (std::size_t i = 0; i < frames; ++i) {
    box.extend(trajectory.T_world_sonar(i).translation().head<2>());
  }
  const double reach = sonar.range().maxRange();
  return Eigen::AlignedBox2d(box.min().array() - reach, box.max().array() + reach);
}

}  // namespace

SonarModel paperSonar(const std::string& id) {
  return SonarModel(id, RangeBins{0.0, 0.02, 500}, BearingTable::uniform(degToRad(130.0), 650),
                    degToRad(20.0));
}

SimulationResult runSimulation(const SimulationRequest& request, Progress& progress,
                               ThreadPool& pool, const std::optional<SeabedFieldSpec>& field_spec,
                               const SeabedReliefSpec& relief) {
  const std::optional<SeabedField> field =
      field_spec ? std::optional<SeabedField>(SeabedField(*field_spec)) : std::nullopt;
  const Trajectory trajectory =
      makeTrajectory(request.trajectory, field ? field->target() : request.scene.target);
  std::size_t frames = trajectory.poses.size();
  if (request.max_frames && *request.max_frames >= 0) {
    frames = std::min(frames, static_cast<std::size_t>(*request.max_frames));
  }
  FrameRenderer renderer = field
                               ? FrameRenderer(*field, request.sonar, request.imaging, pool)
                               : FrameRenderer(request.scene, request.sonar, request.imaging, pool);
  const std::string scene_name = field ? std::string("seabed-field") : request.scene.name;
  const bool keep_visible = request.imaging.visible_cell_m > 0.0;
  VisibleSurface visible(keep_visible ? request.imaging.visible_cell_m : 0.01);
  const HitSink seen = [&](std::span<const Eigen::Vector3f> points) { visible.add(points); };
  // A clipped beam images nothing outside the aperture: the mission says so, for carving. A
  // realistic one given a horizontal beam width says how wide, so that its blur across
  // bearing can be taken out (sonar/bearing_deblur.h).
  // The elevation beam it declares may differ from the simulated one (SimulationRequest).
  const bool clipped = request.imaging.beam == SimulatedBeam::Clipped;
  const ElevationBeam declared = request.declared_beam.value_or(
      clipped ? ElevationBeam::Clipped : request.sonar.elevationBeam());
  const SonarModel mission_sonar =
      clipped ? request.sonar.withElevationBeam(declared)
              : request.sonar.withElevationBeam(declared).withHorizontalBeamWidth(
                    request.imaging.horizontal_beam_width_rad);
  MissionWriter writer(
      request.output,
      scene_name + (request.empty_water ? " (empty water)" : "") + " / " + request.trajectory.kind,
      mission_sonar, trajectory.mounting);
  SimulationResult result;
  {
    const FrameNoise noise(request.noise, mission_sonar);
    // Each frame is noised, encoded and written while the next one renders; two wait at most.
    // (Declared after what its jobs use: on the way out it stops before they go.)
    SerialWorker frame_writer(2);
    // The sonar saturates at its full scale: 65535 counts of power, or its scale's top.
    const IntensityScale& scale = mission_sonar.intensityScale();
    const auto saturation = static_cast<float>(scale.isLinear() ? 65535.0 : scale.fullScalePower());
    for (std::size_t i = 0; i < frames; ++i) {
      if (progress.cancelled()) {
        result.cancelled = true;
        break;
      }
      Frame frame{trajectory.poses[i].time_s, request.sonar.id(), {}};
      if (request.empty_water) {
        frame.image = cv::Mat(request.sonar.rows(), request.sonar.cols(), CV_32F, cv::Scalar(0.0f));
      } else {
        frame.image = renderer.render(trajectory.T_world_sonar(i), keep_visible ? seen : HitSink{});
      }
      frame_writer.submit([&noise, &writer, i, saturation, frame = std::move(frame)]() mutable {
        noise.add(frame.image, i);
        cv::min(frame.image, saturation, frame.image);
        writer.addFrame(frame);
      });
      ++result.frames_written;
      progress.report("simulate", i + 1, frames);
    }
    frame_writer.finish();
  }
  const std::size_t written = result.frames_written;
  if (written == 0) {
    throw Error(request.output.string(), "", "no frame simulated (cancelled before the first)");
  }
  // The mission's navigation covers the frames written, with the chosen error.
  std::vector<NavSample> truth(trajectory.poses.begin(),
                               trajectory.poses.begin() + static_cast<std::ptrdiff_t>(written));
  if (truth.size() == 1) {  // one pose is a track of one instant: frames at that time are in it
    truth.push_back(truth.front());
    truth.back().time_s += 1e-3;
  }
  writer.finish(NavTrack(withNavigationError(truth, request.nav_error)));
  writeFileAtomically(request.output / "ground_truth_poses.csv", navCsvText(NavTrack(truth)));
  const Scene ground_truth =
      field ? field->area(reachOf(trajectory, written, request.sonar)) : Scene{};
  writeScenePly(field ? ground_truth : request.scene, request.output / "ground_truth.ply");
  if (!request.empty_water && keep_visible) {
    writePointsPly(visible.points(), request.output / "visible_points.ply");
  }
  writeFileAtomically(
      request.output / "simulation.yaml",
      settingsYaml(request, field_spec, relief, written, renderer.tracedElevation(), declared));
  result.visible_points = visible.size();
  result.most_triangles_traced = renderer.mostTriangles();
  result.ground_truth_triangles =
      field ? ground_truth.triangles.size() : request.scene.triangles.size();
  return result;
}

}  // namespace sonarcarve
