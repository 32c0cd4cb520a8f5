// ForwardModel: predicts a polar frame of the imaging sonar from a surface (model/block_grid.h),
// a pose, an elevation beam profile (model/elevation_profile.h), a gain and a background per
// range bin, and gives the derivatives of a loss of that frame in all of them (docs/model.md).
//
// For beam b (its centre bearing phi_b) and range bin k:
//   I(b, k) = G * sum over elevation samples j of  s * p(theta_j) cos(theta_j) * E_j(k)  + B(k)
//   E_j(k)  = sum over ray samples i of ray (phi_b, theta_j) in bin k of
//             T_i * alpha_i * rho_i * max(0, cos incidence_i)
// with s = dtheta / A the sample scale and p(theta) cos(theta) the solid-angle weight of the
// simulator's realistic beam (model/elevation_fan.h), the Lambertian return of
// model/reflectance.h, the ray sampling of model/ray_march.h and the range bins of
// model/range_deposit.h. cos incidence = d . g / |g|, d the ray's direction and g the occupancy
// gradient (model/voxel_stencil.h). A wall of alpha = 1 facing the sonar across the aperture
// thus returns what the simulator's realistic beam returns for it, per unit of gain.
// One ray per beam at the beam's centre bearing: no bearing leakage (p_az) yet.
// Frames are CV_64F, rows = range bins, cols = beams, as SonarModel lays them out.
// Thread safe; each call runs its beams in parallel on the pool.
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <span>
#include <vector>

#include "common/thread_pool.h"
#include "model/block_grid.h"
#include "model/elevation_profile.h"
#include "model/model_gradient.h"
#include "model/ray_march.h"
#include "sonar/sonar_model.h"

namespace sonarcarve {

struct ModelSettings {
  double elevation_step_rad = 0.2 * 3.14159265358979323846 / 180.0;
  int samples_per_bin = 2;          ///< ray samples per range bin
  double min_alpha = 1e-3;          ///< samples less occupied count as empty
  double min_transmittance = 1e-4;  ///< a ray stops when less than this gets through
  /// Only beams beam_offset, beam_offset + beam_stride, ... are traced; the others' columns
  /// are predicted empty (the background alone) and take no gradient (nor give the
  /// background any). A fit that alternates
  /// the offset between its steps sees every beam at a fraction of the cost.
  int beam_stride = 1;
  int beam_offset = 0;
};

/// Everything but the surface that the frame depends on.
struct FrameView {
  Eigen::Isometry3d T_world_sonar = Eigen::Isometry3d::Identity();
  ElevationProfile profile;
  double gain = 1.0;
  std::vector<double> background;  ///< per range bin; empty: 0 everywhere
};

/// One elevation ray of one beam, and what its samples are weighted by.
struct ModelRay {
  int beam = 0;
  double elevation_rad = 0.0;
  Eigen::Vector3d direction_sonar;
  Eigen::Vector3d direction_world;
  double unit_scale = 0.0;   ///< dtheta / A
  double scale = 0.0;        ///< G * dtheta / A
  double beam_weight = 0.0;  ///< p(theta) cos(theta)
  double power = 0.0;        ///< p(theta)
};

/// The samples of every ray of one frame that met the surface: one march that the prediction
/// and the gradient share. It keeps the samples' values, not the voxels they read (which the
/// gradient reads again where it needs them: a fifteenth of the memory). Kept between frames,
/// it keeps its memory.
class FrameTrace {
 public:
  std::size_t samples() const;

 private:
  friend class ForwardModel;
  struct Beam {
    std::vector<ModelRay> rays;
    std::vector<std::size_t> ends;  ///< ray r's samples end at ends[r]
    std::vector<SampleValues> samples;
    std::span<const SampleValues> of(std::size_t r) const {
      const std::size_t begin = r == 0 ? 0 : ends[r - 1];
      return {samples.data() + begin, ends[r] - begin};
    }
  };
  std::vector<Beam> beams_;  ///< per traced beam
  Eigen::Vector3d origin_;   ///< of the rays, world frame
};

class ForwardModel {
 public:
  /// `sonar` and `pool` must outlive the model. Throws Error on invalid settings.
  ForwardModel(const SonarModel& sonar, ModelSettings settings, ThreadPool& pool);

  /// The predicted frame.
  cv::Mat predict(const BlockGrid& grid, const FrameView& view) const;
  /// d loss / d parameters, given d loss / d I for every pixel (CV_64F, the frame's size).
  ModelGradient gradient(const BlockGrid& grid, const FrameView& view,
                         const cv::Mat& dloss_dframe) const;

  /// Marches every ray of the frame once, into `trace`, for predict and gradient below, which
  /// equal the two above as long as the grid and the view stay as they were traced.
  void trace(const BlockGrid& grid, const FrameView& view, FrameTrace& trace) const;
  cv::Mat predict(const FrameTrace& trace, const FrameView& view) const;
  ModelGradient gradient(const FrameTrace& trace, const BlockGrid& grid, const FrameView& view,
                         const cv::Mat& dloss_dframe) const;

  const ModelSettings& settings() const { return settings_; }

 private:
  /// How many beams the settings' stride and offset trace.
  int tracedBeams() const;
  template <typename RayBody>
  void forEachRay(const BlockGrid& grid, const FrameView& view, const RayBody& body) const;
  template <typename RayBody>
  void forEachTracedRay(const FrameTrace& trace, const RayBody& body) const;
  template <typename Sample>
  void deposit(const ModelRay& ray, std::span<const Sample> samples, cv::Mat& columns) const;

  const SonarModel& sonar_;
  ModelSettings settings_;
  ThreadPool& pool_;
};

}  // namespace sonarcarve
