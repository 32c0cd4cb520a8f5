// FrameRenderer: the simulator's images of a scene, or of a seabed field of any extent. A scene
// is traced as a whole; of a field (sim/seabed_field.h) only the tiles within the sonar's reach
// (its maximum range) are built and traced, and they are rebuilt, with a tile's margin, when
// the sonar leaves them: the triangles held stay bounded however long the mission.
#pragma once

#include <memory>
#include <optional>

#include "sim/seabed_field.h"
#include "sim/sonar_simulator.h"

namespace sonarcarve {

class FrameRenderer {
 public:
  /// `sonar` and `pool` must outlive the renderer.
  FrameRenderer(const Scene& scene, const SonarModel& sonar, ImagingSettings imaging,
                ThreadPool& pool);
  FrameRenderer(const SeabedField& field, const SonarModel& sonar, ImagingSettings imaging,
                ThreadPool& pool);
  ~FrameRenderer();

  /// Noise-free image seen from `T_world_sonar` (SonarSimulator::render).
  cv::Mat render(const Eigen::Isometry3d& T_world_sonar, const HitSink& hits = {});
  /// Elevation traced on each side of the axis, radians (known once a frame is rendered).
  double tracedElevation() const { return traced_elevation_rad_; }
  /// The most triangles held at once, and how many times a field's tiles were rebuilt.
  std::size_t mostTriangles() const { return most_triangles_; }
  std::size_t rebuilds() const { return rebuilds_; }

 private:
  void build(const Scene& scene);
  void followSonar(const Eigen::Vector3d& sonar_position);

  const SonarModel& sonar_;
  ImagingSettings imaging_;
  ThreadPool& pool_;
  std::optional<SeabedField> field_;
  Eigen::AlignedBox2d built_;  // north-east box of the field's tiles in the caster
  std::unique_ptr<RayCaster> caster_;
  std::unique_ptr<SonarSimulator> simulator_;
  double traced_elevation_rad_ = 0.0;
  std::size_t most_triangles_ = 0;
  std::size_t rebuilds_ = 0;
};

}  // namespace sonarcarve
