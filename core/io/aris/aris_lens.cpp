#include "io/aris/aris_lens.h"

#include <array>

#include "common/angles.h"

namespace sonarcarve {
namespace {

// Beam centres of the ARIS telephoto lens with 48 beams, degrees, from ARIS beam 0 (the
// right-most) to beam 47. Source: Sound Metrics' ARIS file SDK,
// beam-width-metrics/BeamWidths_ARIS_Telephoto_48.h ("average of 4 ARIS Telephoto
// beampatterns"). The table is symmetric, so ARIS beam b's centre taken with its sign flipped
// (ARIS beams count right to left) is our column (47 - b)'s bearing: the same numbers, in
// order, are our columns' bearings from port to starboard.
constexpr std::array<double, 48> kTelephoto48Deg = {
    -6.742, -6.473, -6.204, -5.934, -5.665, -5.396, -5.126, -4.839, -4.552, -4.265, -3.978, -3.690,
    -3.403, -3.116, -2.829, -2.541, -2.254, -1.967, -1.680, -1.374, -1.069, -0.764, -0.459, -0.154,
    0.154,  0.459,  0.764,  1.069,  1.374,  1.680,  1.967,  2.254,  2.541,  2.829,  3.116,  3.403,
    3.690,  3.978,  4.265,  4.552,  4.839,  5.126,  5.396,  5.665,  5.934,  6.204,  6.473,  6.742};

}  // namespace

ArisLensBeams arisLensBeams(std::uint32_t beams, bool large_lens) {
  ArisLensBeams lens;
  if (large_lens && beams == kTelephoto48Deg.size()) {
    for (const double deg : kTelephoto48Deg) {
      lens.centres_rad.push_back(degToRad(deg));
    }
    lens.source = "ARIS telephoto lens, 48 beams (SDK BeamWidths_ARIS_Telephoto_48.h)";
    lens.measured = true;
    return lens;
  }
  const double fov_deg = large_lens ? 15.0 : (beams == 64 || beams == 128 ? 30.0 : 28.0);
  const double step = fov_deg / beams;
  for (std::uint32_t b = 0; b < beams; ++b) {
    lens.centres_rad.push_back(degToRad(-fov_deg / 2.0 + step * (b + 0.5)));
  }
  lens.source = "uniform over " + std::to_string(static_cast<int>(fov_deg)) +
                " degrees (no measured table built in for this lens and beam count)";
  return lens;
}

}  // namespace sonarcarve
