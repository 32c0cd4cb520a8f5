// The beam check (pipeline/beam_check.h): a sonar declared with a real beam's tails whose
// frames show none (simulated with the clipped beam: nothing past +-aperture/2) is carved
// inside its aperture and says so, instead of an empty map; a beam as declared is left as it
// is; a run that keeps no surface says so.
#include <gtest/gtest.h>

#include "pipeline/reconstruction.h"
#include "pipeline/surface_kept.h"
#include "sim/demo_scenes.h"
#include "sim/elevation_pattern.h"
#include "sim/simulation_run.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

class BeamCheck : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::ScratchDir();
    simulate("clipped", test::clippedBeam(), false);
    simulate("realistic", ImagingSettings{}, false);
    simulate("empty", ImagingSettings{}, true);
    ImagingSettings cut;  // sinc^2 cut to nothing past its -6 dB points; declared sinc^2
    cut.elevation_beam.family = ElevationFamily::Truncated;
    simulate("cut", cut, false);
  }
  static void TearDownTestSuite() { delete dir_; }

  static void simulate(const std::string& name, const ImagingSettings& imaging, bool empty) {
    SimulationRequest request{makeDemoScene("riser"), "riser", paperSonar(),
                              TrajectorySpec{},       imaging, NoiseSpec::none(),
                              NavErrorSpec{},         empty,   24,
                              dir_->path() / name};
    SilentProgress progress;
    ThreadPool pool(2);
    runSimulation(request, progress, pool);
  }

  static ReconstructionResult reconstruct(const Mission& mission, double dynamic_range_db = 20.0) {
    static ThreadPool pool(2);
    ReconstructionParams params;
    params.mesh_enabled = false;
    params.carve.dynamic_range_db = dynamic_range_db;
    SilentProgress progress;
    return Pipeline(mission, params, pool).run(progress);
  }

  static Mission mission(const std::string& name) { return readMission(dir_->path() / name); }
  static test::ScratchDir* dir_;
};
test::ScratchDir* BeamCheck::dir_ = nullptr;

TEST_F(BeamCheck, ABeamWithoutTailsDeclaredWithThemIsCarvedInsideItsAperture) {
  const Mission as_recorded = mission("clipped");
  ASSERT_EQ(as_recorded.sonar.elevationBeam(), ElevationBeam::Clipped);
  Mission declared_sinc = as_recorded;  // a spec sheet's pattern, wrong in its tails
  declared_sinc.sonar = as_recorded.sonar.withElevationBeam(ElevationBeam::MainLobe);

  const ReconstructionResult right = reconstruct(as_recorded);
  const ReconstructionResult checked = reconstruct(declared_sinc);
  const RunChoice* beam = findChoice(checked.choices, "elevation beam");
  ASSERT_NE(beam, nullptr);
  EXPECT_EQ(beam->value, "carved inside the aperture") << beam->detail;
  EXPECT_TRUE(beam->warning);
  // Carved as the beam really is: the same map as with the pattern declared right.
  ASSERT_GT(right.surface.size(), 100u);
  EXPECT_EQ(checked.surface.size(), right.surface.size());
  EXPECT_EQ(checked.occupied_voxels, right.occupied_voxels);
  EXPECT_EQ(findChoice(checked.choices, "surface"), nullptr);  // not empty
  // The clipped sonar is not checked: nothing is carved past its aperture anyway.
  EXPECT_EQ(findChoice(right.choices, "elevation beam"), nullptr);
}

TEST_F(BeamCheck, ABeamAsDeclaredIsLeftAsDeclared) {
  const ReconstructionResult result = reconstruct(mission("realistic"));
  const RunChoice* beam = findChoice(result.choices, "elevation beam");
  ASSERT_NE(beam, nullptr);
  EXPECT_EQ(beam->value, "as declared") << beam->detail;
  EXPECT_FALSE(beam->warning);
  // Enough views to have checked, not too few to tell.
  EXPECT_EQ(beam->reason.find("too few"), std::string::npos) << beam->detail;
  EXPECT_GT(result.surface.size(), 100u);
}

TEST_F(BeamCheck, ABeamCutShortOfItsDeclaredNullIsCarvedOutToItsCut) {
  const Mission cut = mission("cut");
  ASSERT_EQ(cut.sonar.elevationBeam(), ElevationBeam::MainLobe);  // declared with its tails
  const ReconstructionResult result = reconstruct(cut);
  const RunChoice* reach = findChoice(result.choices, "elevation beam reach");
  ASSERT_NE(reach, nullptr);
  EXPECT_TRUE(reach->warning) << reach->detail;
  // The cut lies at 13.6 degrees (sinc^2's -6 dB point for a 20 degree aperture); the reach is
  // a half-degree band's edge, found up to a view's spacing past the cut (5 cm of descent at
  // 5 m: 0.6 degree).
  const double reach_deg = std::stod(reach->value);
  EXPECT_GE(reach_deg, 13.6 - 0.5) << reach->detail;
  EXPECT_LE(reach_deg, 13.6 + 0.5 + 0.6) << reach->detail;
  // Carved as deep as the beam reaches: the surface the matched beam keeps, not an empty map.
  const ReconstructionResult matched = reconstruct(mission("realistic"));
  EXPECT_GT(result.surface.size(), matched.surface.size() / 2);
  EXPECT_EQ(findChoice(result.choices, "surface"), nullptr);
  const RunChoice* kept = findChoice(result.choices, "first surface kept");
  ASSERT_NE(kept, nullptr);
  EXPECT_FALSE(kept->warning) << kept->detail;
  const RunChoice* as_declared = findChoice(matched.choices, "elevation beam reach");
  ASSERT_NE(as_declared, nullptr);
  EXPECT_FALSE(as_declared->warning) << as_declared->detail;
}

TEST_F(BeamCheck, ARunThatCarvesAwayMostOfAFirstCarveSaysSo) {
  // A keep level 10 dB under the bright returns carves away every surface that returns less:
  // most of what a first carve inside the aperture kept (18 % is left; at 6 dB nothing is,
  // and the "surface" choice says so).
  const ReconstructionResult thin = reconstruct(mission("realistic"), 10.0);
  const RunChoice* kept = findChoice(thin.choices, "first surface kept");
  ASSERT_NE(kept, nullptr);
  EXPECT_TRUE(kept->warning) << kept->detail;
  EXPECT_LT(std::stod(kept->value), 100.0 * kKeptFirstSurfaceShare);
  // At the default keep level the run keeps it, less the first carve's ghosts.
  const ReconstructionResult full = reconstruct(mission("realistic"));
  const RunChoice* as_carved = findChoice(full.choices, "first surface kept");
  ASSERT_NE(as_carved, nullptr);
  EXPECT_FALSE(as_carved->warning) << as_carved->detail;
  EXPECT_GT(full.surface.size(), thin.surface.size());
}

TEST_F(BeamCheck, ARunThatKeepsNoSurfaceSaysSo) {
  const ReconstructionResult result = reconstruct(mission("empty"));
  EXPECT_TRUE(result.surface.empty());
  const RunChoice* surface = findChoice(result.choices, "surface");
  ASSERT_NE(surface, nullptr);
  EXPECT_EQ(surface->value, "empty");
  EXPECT_TRUE(surface->warning);
  EXPECT_FALSE(surface->reason.empty());
}

}  // namespace
}  // namespace sonarcarve
