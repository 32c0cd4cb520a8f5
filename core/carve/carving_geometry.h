// CarvingGeometry: what the carving kernels need to know of the sonar, precomputed once:
// the range window in effect, squared limits, the elevation bound as sin^2 and a fine
// bearing -> beam lookup table (exact for uniform tables, 1/16 of the narrowest beam for
// explicit ones), the beam-aware elevation extent with a table of the beam's inverse gain,
// plus the frustum's bounding box in the world for a given pose.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "carve/carve_params.h"
#include "sonar/sonar_model.h"

namespace sonarcarve {

/// Whether carving is beam-aware (CarveParams::beam_aware) for this sonar: not for a clipped
/// beam.
bool carvesMainLobe(const SonarModel& sonar, const CarveParams& params);

class CarvingGeometry {
 public:
  CarvingGeometry(const SonarModel& sonar, const CarveParams& params);

  const SonarModel& sonar() const { return sonar_; }
  double rangeMin() const { return range_min_; }
  double rangeMax() const { return range_max_; }
  /// Beam of a bearing, or -1 outside the field of view.
  int beamOf(float bearing_rad) const {
    const float u = (bearing_rad - lut_left_) * lut_inv_step_;
    if (!(u >= 0.0f) || u >= static_cast<float>(lut_.size())) {
      return -1;
    }
    return lut_[static_cast<std::size_t>(u)];
  }
  /// Elevation carved on each side of the axis: the main lobe's first null when beam-aware (or
  /// the sonar's elevation reach, when set short of it), else aperture/2.
  double carvedHalfElevation() const { return carved_half_elevation_; }
  /// 1 / p(theta) of the sinc^2 beam for |sin(theta)| = s, s in [0, sin(carvedHalfElevation)]
  /// (beam-aware only); capped at 1e6 near the null.
  float inverseGain(float s) const {
    const auto i = static_cast<std::size_t>(s * inverse_gain_scale_);
    return inverse_gain_[std::min(i, inverse_gain_.size() - 1)];
  }
  /// Bounding box of the frustum (range window x field of view x carved elevation, or
  /// +-`half_elevation` when given) in the world.
  Eigen::AlignedBox3d frustumBounds(const Eigen::Isometry3d& T_world_sonar,
                                    double half_elevation = -1.0) const;
  /// Whether a sphere (sonar frame) may touch the frustum within +-aperture/2 (what
  /// occlusion resolution looks at); conservative.
  bool sphereMayTouchFrustum(const Eigen::Vector3d& centre_sonar, double radius) const {
    return sphereMayTouchFrustum(centre_sonar, radius, sin_half_aperture_, cos_half_aperture_);
  }
  /// The same within +-half elevation given by its sine and cosine.
  bool sphereMayTouchFrustum(const Eigen::Vector3d& centre_sonar, double radius, double sin_half,
                             double cos_half) const;

  /// Inward unit normals (sonar frame, z = 0) of the planes bounding the field of view's
  /// bearings: p is inside the bearing wedge where both dot products with p are >= 0.
  const Eigen::Vector3d& leftNormal() const { return left_normal_; }
  const Eigen::Vector3d& rightNormal() const { return right_normal_; }

  float rangeMinSq() const { return range_min_sq_; }
  float rangeMaxSq() const { return range_max_sq_; }
  float sinHalfApertureSq() const { return sin_half_aperture_sq_; }
  float binMin() const { return static_cast<float>(sonar_.range().min_m); }
  float binInvResolution() const { return static_cast<float>(1.0 / sonar_.range().resolution_m); }

 private:
  const SonarModel& sonar_;
  double range_min_;
  double range_max_;
  float range_min_sq_;
  float range_max_sq_;
  float sin_half_aperture_sq_;
  double sin_half_aperture_;
  double cos_half_aperture_;
  double carved_half_elevation_;
  std::vector<float> inverse_gain_;
  float inverse_gain_scale_ = 0.0f;
  Eigen::Vector3d left_normal_;  // inward normals of the bearing wedge's boundary planes
  Eigen::Vector3d right_normal_;
  std::vector<std::int16_t> lut_;
  float lut_left_;
  float lut_inv_step_;
};

/// atan2 to about 1e-5 rad (0.0006 degree), several times faster than std::atan2.
inline float fastAtan2(float y, float x) {
  const float ax = std::abs(x);
  const float ay = std::abs(y);
  const bool swap = ay > ax;
  const float t = swap ? ax / ay : (ax > 0.0f ? ay / ax : 0.0f);
  const float t2 = t * t;
  float a =
      t * (0.99997726f +
           t2 * (-0.33262347f +
                 t2 * (0.19354346f + t2 * (-0.11643287f + t2 * (0.05265332f - t2 * 0.01172120f)))));
  if (swap) {
    a = 1.57079632679f - a;
  }
  if (x < 0.0f) {
    a = 3.14159265359f - a;
  }
  return y < 0.0f ? -a : a;
}

}  // namespace sonarcarve
