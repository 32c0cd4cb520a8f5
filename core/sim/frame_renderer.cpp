#include "sim/frame_renderer.h"

namespace sonarcarve {

FrameRenderer::FrameRenderer(const Scene& scene, const SonarModel& sonar, ImagingSettings imaging,
                             ThreadPool& pool)
    : sonar_(sonar), imaging_(imaging), pool_(pool) {
  build(scene);
}

FrameRenderer::FrameRenderer(const SeabedField& field, const SonarModel& sonar,
                             ImagingSettings imaging, ThreadPool& pool)
    : sonar_(sonar), imaging_(imaging), pool_(pool), field_(field) {}

FrameRenderer::~FrameRenderer() = default;

void FrameRenderer::build(const Scene& scene) {
  simulator_.reset();
  caster_.reset();
  caster_ = std::make_unique<RayCaster>(scene);
  simulator_ = std::make_unique<SonarSimulator>(*caster_, sonar_, imaging_, pool_);
  traced_elevation_rad_ = simulator_->tracedElevation();
  most_triangles_ = std::max(most_triangles_, scene.triangles.size());
  ++rebuilds_;
}

void FrameRenderer::followSonar(const Eigen::Vector3d& sonar_position) {
  // No ray goes farther than the last range bin.
  const double reach = sonar_.range().maxRange() + 0.1;
  const Eigen::Vector2d at = sonar_position.head<2>();
  const Eigen::AlignedBox2d needed(at.array() - reach, at.array() + reach);
  if (caster_ && built_.contains(needed)) {
    return;
  }
  // A tile's margin on every side, so that the next rebuild is a tile's travel away.
  const double margin = field_->spec().tile_m;
  const Eigen::AlignedBox2d wanted(needed.min().array() - margin, needed.max().array() + margin);
  const Eigen::Vector2i lo = field_->tileOf(wanted.min().x(), wanted.min().y());
  const Eigen::Vector2i hi = field_->tileOf(wanted.max().x(), wanted.max().y());
  const double tile = field_->spec().tile_m;
  built_ = Eigen::AlignedBox2d(tile * lo.cast<double>(),
                               tile * (hi + Eigen::Vector2i::Ones()).cast<double>());
  build(field_->area(wanted));
}

cv::Mat FrameRenderer::render(const Eigen::Isometry3d& T_world_sonar, const HitSink& hits) {
  if (field_) {
    followSonar(T_world_sonar.translation());
  }
  return simulator_->render(T_world_sonar, hits);
}

}  // namespace sonarcarve
