// Elevation beam pattern of an imaging sonar: the weight b(theta) that a return at elevation
// theta gets in the pixel that images it.
//
// b is an intensity (power) weight: b(0) = 1 and b(+-aperture/2) = 10^(-3/10) (-3 dB), with a
// sinc shape b(theta) = sin(k theta) / (k theta) as in the seed paper. Only the main lobe is
// modelled: b is 0 beyond the first null at |k theta| = pi, where the sinc turns negative.
#pragma once

namespace sonarcarve {

class BeamPattern {
 public:
  /// `aperture_rad`: full vertical aperture between the -3 dB points (> 0).
  explicit BeamPattern(double aperture_rad);

  double aperture() const { return aperture_rad_; }
  /// Weight in [0, 1] of a return at `elevation_rad`.
  double weight(double elevation_rad) const;
  /// Elevation of the first null (b = 0), radians; about 1.66 times aperture/2.
  double firstNull() const;

 private:
  double aperture_rad_;
  double k_;  // sinc argument per radian of elevation
};

/// The x > 0 where sin(x) / x equals 10^(-3/10): the -3 dB point of the sinc main lobe.
double sincMinus3dBArgument();

}  // namespace sonarcarve
