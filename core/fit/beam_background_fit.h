// BeamBackgroundFit: the parts of the frames' view (model/forward_model.h, FrameView) that the
// fit takes from the mission's own frames beside the map (issue 41: a declared parameter is a
// prior, not the truth).
// - The elevation profile's knots, in dB: its shape only. After each step its peak is put
//   back at 0 dB and the level goes into the gain (the gain and the reflectance carry it).
// - The background per range bin, as its logarithm, never below the floor.
// Both by Adam down the gradient of the frames' speckle NLL plus, for the profile, two priors
// counted per pixel of the step on its correction to the declared profile (dB): smoothness
// (the square of the correction's second differences) and smallness. The second is weak: it holds
// the profile only where no frame says otherwise (elevations at which nothing was ever seen).
#pragma once

#include <vector>

#include "fit/adam.h"
#include "model/elevation_profile.h"
#include "model/forward_model.h"
#include "model/model_gradient.h"

namespace sonarcarve {

struct BeamBackgroundSettings {
  bool beam = true;        ///< fit the elevation profile
  bool background = true;  ///< fit the background
};

class BeamBackgroundFit {
 public:
  BeamBackgroundFit(const FrameView& declared, double background_floor,
                    BeamBackgroundSettings settings);

  /// One step of `view`'s profile and background down `gradient`, the gradient of the NLL of
  /// `pixels` pixels (the step's frames), at `share` of the learning rates.
  void step(FrameView& view, const ModelGradient& gradient, double pixels, double share);

  /// The profile's prior loss per pixel (smoothness and closeness to the declared), for tests.
  double priorPerPixel(const ElevationProfile& profile) const;

 private:
  std::vector<double> priorGradient(const std::vector<double>& knots_db) const;
  std::vector<double> correction(const std::vector<double>& knots_db) const;  ///< - declared

  std::vector<double> declared_db_;
  double floor_;
  BeamBackgroundSettings settings_;
  AdamState knot_steps_;
  AdamState background_steps_;
  std::vector<double> log_background_;
};

}  // namespace sonarcarve
