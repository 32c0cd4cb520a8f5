// The beam centre bearings of ARIS lenses, for our image columns (port to starboard).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace sonarcarve {

struct ArisLensBeams {
  std::vector<double> centres_rad;  ///< increasing, port to starboard
  std::string source;               ///< where the table comes from, for `info`
  bool measured = false;            ///< false: uniform over the lens's nominal field of view
};

/// The beam centres of an ARIS with `beams` beams and this lens (large_lens: telephoto).
/// Measured for the telephoto lens with 48 beams; otherwise uniform over the nominal field of
/// view (28 degrees for ARIS 1200/1800 lenses, 30 for the ARIS 3000, 15 for the telephoto).
ArisLensBeams arisLensBeams(std::uint32_t beams, bool large_lens);

}  // namespace sonarcarve
