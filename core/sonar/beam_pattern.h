// Beam patterns of an imaging sonar: the power weight that a return at an angle off a beam's
// axis gets in the pixel that images it.
//
// BeamPattern, in elevation, is the seed paper's model and what the carving engines assume:
// b(0) = 1 and b(+-aperture/2) = 10^(-3/10) (-3 dB), with a sinc shape
// b(theta) = sin(k theta) / (k theta). Only the main lobe is modelled: b is 0 beyond the first
// null at |k theta| = pi, where the sinc turns negative.
//
// SincSquaredBeam is a real array's power pattern (a uniformly weighted aperture):
// p(theta) = sinc^2(k theta) = (sin(k theta) / (k theta))^2, with k set so that p = -3 dB at
// +-width/2 (k width/2 = 1.3894). Its main lobe reaches the first null at pi / k = 2.261
// times width/2 (+-22.6 degrees for a 20 degree aperture); the first side lobes peak at
// -13.26 dB at 4.4934 / k (3.234 times width/2, +-32.3 degrees) and end at the second null,
// 2 pi / k (+-45.2 degrees).
// The simulator's realistic beam uses it in elevation and in bearing.
#pragma once

#include <vector>

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

class SincSquaredBeam {
 public:
  /// `width_rad`: full width between the -3 dB points (> 0).
  explicit SincSquaredBeam(double width_rad);

  double width() const { return width_rad_; }
  /// Power in [0, 1] of a return at `angle_rad` off the axis, side lobes included.
  double power(double angle_rad) const;
  /// The field's amplitude there, sinc(k angle): its square is power(); negative in odd side
  /// lobes.
  double amplitude(double angle_rad) const;
  /// Angle of the n-th null (n >= 1): n pi / k.
  double null(int n) const;
  /// Angle of the peak of the n-th side lobe (n >= 1), where tan(k theta) = k theta.
  double sideLobePeak(int n) const;
  /// Half-angle of the main lobe at which the power falls to `level_db` (< 0 dB).
  double halfAngleAt(double level_db) const;

 private:
  double width_rad_;
  double k_;  // sinc argument per radian
};

/// A sinc^2 beam's pattern averaged over each beam's interval of bearing, for beams
/// `spacing_rad` apart: the weights from beam -half to +half, out to the pattern's second null
/// (as the simulator traces it) and at most `max_half`. `amplitude`: the field's pattern
/// (sinc) rather than the power's (sinc^2).
std::vector<double> meansOverBeams(const SincSquaredBeam& beam, double spacing_rad, int max_half,
                                   bool amplitude);

/// The x > 0 where sin(x) / x equals 10^(-3/10): the -3 dB point of the sinc main lobe.
double sincMinus3dBArgument();
/// The x > 0 where (sin(x) / x)^2 equals 10^(-3/10) (about 1.3894).
double sincSquaredMinus3dBArgument();

}  // namespace sonarcarve
