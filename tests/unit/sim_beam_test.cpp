// The simulator's beams (sim/sonar_simulator.h): the realistic beam against the sinc^2 power
// pattern in elevation and in bearing, what it reports as seen, and the clipped beam against
// the images of the seed paper's model.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <string>

#include "common/angles.h"
#include "io/files/frame_png.h"
#include "sim/demo_scenes.h"
#include "sim/elevation_pattern.h"
#include "sim/ray_caster.h"
#include "sim/simulation_run.h"
#include "sim/sonar_simulator.h"
#include "sim/trajectory.h"
#include "sonar/beam_pattern.h"
#include "support/sim_scenes.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

ThreadPool& pool() {
  static ThreadPool instance(2);
  return instance;
}

using test::sphericalPatch;

constexpr double kRange = 5.0;

// 2 cm bins to 10 m, 41 beams over 40 deg, 20 deg aperture.
SonarModel smallSonar() {
  return SonarModel("test", RangeBins{0.0, 0.02, 500}, BearingTable::uniform(degToRad(40), 41),
                    degToRad(20));
}

ImagingSettings realistic(double elevation_step_deg) {
  ImagingSettings s;
  s.beam = SimulatedBeam::Realistic;
  s.elevation_step_rad = degToRad(elevation_step_deg);
  return s;
}

// Total energy of the image of a band of the sphere of radius kRange around the sonar (at the
// origin, looking north), over elevations [lo, hi] and bearings wider than the traced fan, so
// that every ray between those elevations meets it at normal incidence.
double bandEnergy(const SonarModel& sonar, const ImagingSettings& s, double lo, double hi,
                  const HitSink& hits = {}) {
  const Scene band =
      sphericalPatch(kRange, degToRad(-35), degToRad(35), lo, hi, degToRad(0.05), 0.8f);
  const RayCaster caster(band);
  const SonarSimulator sim(caster, sonar, s, pool());
  return cv::sum(sim.render(Eigen::Isometry3d::Identity(), hits))[0];
}

// Integral of f over [a, b] (Simpson, 2000 intervals).
template <typename F>
double integral(F f, double a, double b) {
  const int n = 2000;
  const double h = (b - a) / n;
  double sum = f(a) + f(b);
  for (int i = 1; i < n; ++i) {
    sum += (i % 2 == 1 ? 4.0 : 2.0) * f(a + i * h);
  }
  return sum * h / 3.0;
}

// What a band over [lo, hi] may gain or lose to the elevation samples, `step` apart: each end
// up to one sample, at most twice the step times the largest weight within a step of an edge.
template <typename F>
double bandEdgeError(F weight, double lo, double hi, double step) {
  double worst = 0.0;
  for (double edge : {lo, hi}) {
    for (double t = edge - step; t <= edge + step; t += 0.1 * step) {
      worst = std::max(worst, weight(t));
    }
  }
  return 2.0 * step * worst;
}

TEST(SimBeam, RealisticElevationBeamFollowsSincSquared) {
  const SonarModel sonar = smallSonar();
  const double step = degToRad(0.01);
  const ImagingSettings settings = realistic(0.01);
  const SincSquaredBeam beam(sonar.verticalAperture());
  // A band of half-height h at elevation c returns, per bearing, the integral of
  // p(theta) cos(theta) over it (cos: the solid angle of a ray's cell), sampled every `step`.
  // Its edges fall anywhere between two samples: each end may gain or lose up to one sample.
  const double h = degToRad(0.5);
  const auto weight = [&](double t) { return beam.power(t) * std::cos(t); };
  const auto edgeError = [&](double c) { return bandEdgeError(weight, c - h, c + h, step); };
  const double on_axis = bandEnergy(sonar, settings, -h, h);
  const double expected_on_axis = integral(weight, -h, h);
  ASSERT_GT(on_axis, 0.0);

  struct Case {
    const char* what;
    double elevation;
  };
  const double half = 0.5 * sonar.verticalAperture();
  const Case cases[] = {
      {"-3 dB, up", half},
      {"-3 dB, down", -half},
      {"first null", beam.null(1)},
      {"first side lobe", beam.sideLobePeak(1)},
      {"first side lobe, down", -beam.sideLobePeak(1)},
  };
  for (const Case& c : cases) {
    const double measured = bandEnergy(sonar, settings, c.elevation - h, c.elevation + h) / on_axis;
    const double expected = integral(weight, c.elevation - h, c.elevation + h) / expected_on_axis;
    const double tolerance =
        (edgeError(c.elevation) + expected * edgeError(0.0)) / expected_on_axis;
    EXPECT_NEAR(measured, expected, tolerance) << c.what;
    // So the band matches sinc^2 at its centre to within its own averaging of the pattern
    // over +-h and that discretisation.
    const double pattern = beam.power(c.elevation) * std::cos(c.elevation);
    EXPECT_NEAR(measured, pattern, tolerance + std::abs(expected - pattern)) << c.what;
  }
  EXPECT_NEAR(10 * std::log10(beam.power(half)), -3.0, 1e-9);
  EXPECT_NEAR(10 * std::log10(beam.power(beam.sideLobePeak(1))), -13.26, 0.005);
  EXPECT_NEAR(beam.null(1) / half, 2.261, 0.001);
  // The null is a minimum and the side lobe a maximum of the image.
  const auto at = [&](double t) { return bandEnergy(sonar, settings, t - h, t + h) / on_axis; };
  const double null_energy = at(beam.null(1));
  EXPECT_LT(null_energy, 1e-3);  // under -30 dB
  EXPECT_LT(null_energy, at(beam.null(1) - degToRad(2)));
  EXPECT_LT(null_energy, at(beam.null(1) + degToRad(2)));
  const double lobe_energy = at(beam.sideLobePeak(1));
  EXPECT_GT(lobe_energy, at(beam.sideLobePeak(1) - degToRad(3)));
  EXPECT_GT(lobe_energy, at(beam.sideLobePeak(1) + degToRad(3)));
  // Traced to the second null, nothing beyond.
  EXPECT_EQ(bandEnergy(sonar, settings, beam.null(2) + step, beam.null(2) + degToRad(3)), 0.0);
}

// Image energy of a band of the sphere at normal incidence, per beam, per unit of gain and of
// reflectivity (0.8): the integral of p(theta) cos(theta) / A over the band's traced part.
double bandResponse(const SonarModel& sonar, const ImagingSettings& s, double lo, double hi) {
  return bandEnergy(sonar, s, lo, hi) / (sonar.cols() * s.gain * 0.8);
}

TEST(SimBeam, EveryElevationFamilyReturnsItsPatternPerUnitOfGain) {
  // A wall across the whole traced beam returns the integral of p cos / A per unit of gain,
  // whatever the family: sinc2's is today's meaning of the counts, the others keep it. The
  // simulator's wall comes out 0.2 to 0.3 % under the integral for every family (sinc2 included,
  // as before the families), so the families are held to that and to sinc2's ratio within 1e-3.
  const SonarModel sonar = smallSonar();
  const double aperture = sonar.verticalAperture();
  ImagingSettings s = realistic(0.02);
  double sinc2_ratio = 0.0;
  for (const auto family :
       {ElevationFamily::Sinc2, ElevationFamily::Gaussian, ElevationFamily::Truncated}) {
    s.elevation_beam.family = family;
    const ElevationPattern pattern(s.elevation_beam, aperture, s.side_lobes);
    const double traced = pattern.tracedHalfAngle();
    const auto weight = [&](double t) { return pattern.power(t) * std::cos(t) / aperture; };
    const double ratio = bandResponse(sonar, s, -traced - degToRad(1), traced + degToRad(1)) /
                         integral(weight, -traced, traced);
    EXPECT_NEAR(ratio, 1.0, 5e-3) << elevationFamilyName(family);
    if (family == ElevationFamily::Sinc2) {
      sinc2_ratio = ratio;
    }
    EXPECT_NEAR(ratio, sinc2_ratio, 1e-3) << elevationFamilyName(family);
    // Nothing beyond the traced extent.
    EXPECT_EQ(bandEnergy(sonar, s, traced + degToRad(0.05), traced + degToRad(3)), 0.0)
        << elevationFamilyName(family);
  }
}

TEST(SimBeam, GaussianElevationBeamFollowsItsPattern) {
  // Bands 1 degree high along the Gaussian, against the integral of its p cos / A over each,
  // within one elevation sample at each edge.
  const SonarModel sonar = smallSonar();
  const double aperture = sonar.verticalAperture();
  ImagingSettings s = realistic(0.01);
  s.elevation_beam.family = ElevationFamily::Gaussian;
  const ElevationPattern pattern(s.elevation_beam, aperture, s.side_lobes);
  const auto weight = [&](double t) { return pattern.power(t) * std::cos(t) / aperture; };
  const double h = degToRad(0.5);
  const double step = s.elevation_step_rad;
  for (const double deg : {0.0, 10.0, -10.0, 20.0, -25.0, 30.0}) {
    const double c = degToRad(deg);
    const double measured = bandResponse(sonar, s, c - h, c + h);
    const double expected = integral(weight, c - h, c + h);
    EXPECT_NEAR(measured, expected, bandEdgeError(weight, c - h, c + h, step)) << deg;
  }
  // Its -3 dB points at +-aperture/2, and -12 dB at twice that.
  const double on_axis = bandResponse(sonar, s, -h, h);
  EXPECT_NEAR(
      10 * std::log10(bandResponse(sonar, s, 0.5 * aperture - h, 0.5 * aperture + h) / on_axis),
      -3.0 + 10 * std::log10(std::cos(0.5 * aperture)), 0.05);
  EXPECT_NEAR(10 * std::log10(bandResponse(sonar, s, aperture - h, aperture + h) / on_axis),
              -12.0 + 10 * std::log10(std::cos(aperture)), 0.1);
}

TEST(SimBeam, SpreadingLossAndGainScaleReturnsWithRange) {
  // Every ray meets the sphere at kRange: the image's energy scales by kRange^(tvg - spreading).
  const SonarModel sonar = smallSonar();
  ImagingSettings s = realistic(0.05);
  const double lo = -degToRad(5), hi = degToRad(5);
  const double plain = bandEnergy(sonar, s, lo, hi);
  s.spreading_exponent = 2.0;
  EXPECT_NEAR(bandEnergy(sonar, s, lo, hi) / plain, std::pow(kRange, -2.0), 1e-4);
  s.tvg_exponent = 1.5;
  EXPECT_NEAR(bandEnergy(sonar, s, lo, hi) / plain, std::pow(kRange, -0.5), 1e-4);
}

TEST(SimBeam, ClippedBeamStopsAtTheAperture) {
  const SonarModel sonar = smallSonar();
  ImagingSettings clipped;
  clipped.beam = SimulatedBeam::Clipped;
  clipped.elevation_step_rad = degToRad(0.01);
  const double half = 0.5 * sonar.verticalAperture();
  EXPECT_GT(bandEnergy(sonar, clipped, half - degToRad(1), half), 0.0);
  EXPECT_EQ(bandEnergy(sonar, clipped, half + degToRad(0.1), half + degToRad(3)), 0.0);
  EXPECT_EQ(bandEnergy(sonar, clipped, -half - degToRad(3), -half - degToRad(0.1)), 0.0);
}

TEST(SimBeam, BearingLeakageFollowsSincSquared) {
  // Beams 4 degrees wide (about four beams at -3 dB) and 8 rays per beam; a target narrower
  // than the ray spacing, centred on one ray, is seen by that ray only: each beam's share is
  // the pattern at its bearing offset from that ray.
  const SonarModel sonar = smallSonar();
  ImagingSettings s = realistic(0.05);
  s.rays_per_beam = 8;
  s.horizontal_beam_width_rad = degToRad(4);
  const SincSquaredBeam beam(s.horizontal_beam_width_rad);
  const int centre = sonar.cols() / 2;
  const double spacing = sonar.bearings().edges()[1] - sonar.bearings().edges()[0];
  const double ray = sonar.bearings().edges()[static_cast<std::size_t>(centre)] + 5.5 * spacing / 8;
  const double half_width = 0.1 * spacing / 8;
  const Scene target = sphericalPatch(kRange, ray - half_width, ray + half_width, degToRad(-3),
                                      degToRad(3), half_width, 0.8f);
  const RayCaster caster(target);
  const SonarSimulator sim(caster, sonar, s, pool());
  const cv::Mat image = sim.render(Eigen::Isometry3d::Identity());
  const double own = cv::sum(image.col(centre))[0];
  ASSERT_GT(own, 0.0);
  const double extent = beam.null(s.side_lobes + 1);
  int lit_beyond_first_null = 0;
  for (int j = 0; j < sonar.cols(); ++j) {
    const double offset = ray - sonar.bearings().centre(j);
    const double measured = cv::sum(image.col(j))[0] / own;
    if (std::abs(offset) >= extent) {
      EXPECT_EQ(measured, 0.0) << "beam " << j;
      continue;
    }
    const double expected = beam.power(offset) / beam.power(ray - sonar.bearings().centre(centre));
    EXPECT_NEAR(measured, expected, 1e-4 * expected + 1e-7) << "beam " << j;
    lit_beyond_first_null += std::abs(offset) > beam.null(1) && measured > 1e-3 ? 1 : 0;
  }
  EXPECT_GT(lit_beyond_first_null, 0);  // the side lobes leak into farther beams
}

TEST(SimBeam, SeenPointsLieWithinTheVisibleBeamLevel) {
  const SonarModel sonar = smallSonar();
  ImagingSettings s = realistic(0.05);
  std::atomic<std::size_t> seen = 0;  // the sink is called from the renderer's threads
  const HitSink count = [&](std::span<const Eigen::Vector3f> points) { seen += points.size(); };
  // At -3 dB (the default) only hits inside +-aperture/2 are seen, though more is imaged.
  EXPECT_GT(bandEnergy(sonar, s, degToRad(11), degToRad(14), count), 0.0);
  EXPECT_EQ(seen.load(), 0u);
  bandEnergy(sonar, s, degToRad(8), degToRad(9.9), count);
  EXPECT_GT(seen.load(), 0u);
  // At -10 dB: out to 16.7 degrees for a 20 degree aperture.
  s.visible_beam_level_db = -10.0;
  seen = 0;
  bandEnergy(sonar, s, degToRad(11), degToRad(14), count);
  EXPECT_GT(seen.load(), 0u);
  seen = 0;
  bandEnergy(sonar, s, degToRad(17), degToRad(19), count);
  EXPECT_EQ(seen.load(), 0u);
}

// Frame `frame` of a demo scene's usual noise-free mission, rendered now, against the one stored
// in tests/data/sim (README.md there): every pixel within 1 count (the rounding to whole counts
// of a value that moved by float rounding), and only a few pixels differing at all. A pixel sums
// about a thousand rays (n) in float, whose order and fused operations differ between processors
// (Embree's kernels for the instruction set at hand): the sum moves by about sqrt(n) times
// float's unit roundoff (2^-24), kFloatDrift relative, which carries a pixel of v counts across
// a half-count boundary with probability 2 kFloatDrift v. The frame may so differ in about
// 2 kFloatDrift times its summed counts; three times that, and at least 5 pixels, are allowed
// (7 of the seabed frame's pixels differ on an AMD EPYC, none on the machine that stored it).
constexpr double kFloatDrift = 1.9e-6;
void expectStoredFrame(const std::string& scene_name, const ImagingSettings& imaging, int frame,
                       const std::string& stored) {
  const cv::Mat before = readFramePng(test::testData(stored));
  const Scene scene = makeDemoScene(scene_name);
  const SonarModel sonar = paperSonar();
  TrajectorySpec spec;
  spec.kind = usualTrajectory(scene_name);
  const Trajectory trajectory = makeTrajectory(spec, scene.target);
  const RayCaster caster(scene);
  const SonarSimulator sim(caster, sonar, imaging, pool());
  const cv::Mat now = sim.render(trajectory.T_world_sonar(static_cast<std::size_t>(frame)));
  ASSERT_EQ(now.size(), before.size());
  int differ = 0;
  const double allowed = std::max(5.0, 3.0 * 2.0 * kFloatDrift * cv::sum(before)[0]);
  for (int r = 0; r < now.rows; ++r) {
    for (int c = 0; c < now.cols; ++c) {
      const double counts =
          static_cast<double>(std::lround(std::min(now.at<float>(r, c), 65535.0f)));
      const double diff = std::abs(counts - before.at<float>(r, c));
      ASSERT_LE(diff, 1.0) << stored << " pixel " << r << ", " << c;
      differ += diff > 0.0 ? 1 : 0;
    }
  }
  EXPECT_LE(differ, allowed) << stored;
  EXPECT_GT(cv::countNonZero(before), 1000) << stored;
}

TEST(SimBeam, ClippedBeamReproducesTheSeedPapersImages) {
  ImagingSettings clipped;
  clipped.beam = SimulatedBeam::Clipped;
  expectStoredFrame("riser", clipped, 45, "sim/riser_clipped_frame45.png");
}

TEST(SimBeam, RealisticBeamReproducesTheOneRayAtATimeImages) {
  // Stored before rays were traced as packets and fans summed in transposed columns.
  expectStoredFrame("riser", ImagingSettings{}, 45, "sim/riser_realistic_frame45.png");
  expectStoredFrame("seabed-objects", ImagingSettings{}, 20,
                    "sim/seabed_objects_realistic_frame20.png");
}

}  // namespace
}  // namespace sonarcarve
