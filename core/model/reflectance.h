// The reflectance law shared by the simulator and the forward model: a Lambertian surface
// returns, into one elevation sample, its reflectivity times cos(incidence) times the sample's
// beam weight and energy scale (model/elevation_fan.h). Multiplied in this order, left to
// right, so that the simulator's frames keep their bits.
#pragma once

namespace sonarcarve {

template <typename Real>
Real lambertianReturn(Real scale, Real reflectivity, Real cos_incidence, Real beam_weight) {
  return scale * reflectivity * cos_incidence * beam_weight;
}

}  // namespace sonarcarve
