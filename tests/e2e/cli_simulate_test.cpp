// End-to-end: sonarcarve-cli simulate and frame, as a user runs them.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "common/angles.h"
#include "io/mesh/point_cloud_ply.h"
#include "io/mission/mission.h"
#include "io/mission/nav_csv.h"
#include "pipeline/frame_stage.h"
#include "sonar/bearing_deblur.h"
#include "support/cli_runner.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

using test::quoted;
using test::runCli;

// The number after "key: " in a settings text, or NaN.
double settingValue(const std::string& text, const std::string& key) {
  const auto at = text.find(key + ": ");
  return at == std::string::npos ? NAN : std::stod(text.substr(at + key.size() + 2));
}

TEST(CliSimulate, WritesARiserMissionThatInfoReads) {
  test::ScratchDir dir;
  const auto out = dir.path() / "riser";
  const auto r = runCli("simulate --scene riser --max-frames 3 --seed 4 --out " + quoted(out));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("wrote 3 frames of 'riser' (vertical)"), std::string::npos) << r.output;
  const Mission mission = readMission(out);
  EXPECT_EQ(mission.frames.size(), 3u);
  EXPECT_EQ(mission.sonar.cols(), 650);
  EXPECT_EQ(mission.sonar.rows(), 500);
  const std::string settings = test::readText(out / "simulation.yaml");
  EXPECT_NE(settings.find("seed: 4"), std::string::npos) << settings;
  // The realistic beam is the default: traced to the second null of a 20 degree sinc^2.
  EXPECT_NE(settings.find("beam: realistic"), std::string::npos) << settings;
  EXPECT_NEAR(settingValue(settings, "traced_elevation_deg"), 45.22, 0.01) << settings;

  // It refuses to overwrite a mission unless told to.
  const auto again = runCli("simulate --scene riser --max-frames 1 --out " + quoted(out));
  EXPECT_NE(again.exit_code, 0);
  EXPECT_NE(again.output.find("already holds a mission"), std::string::npos) << again.output;
  EXPECT_EQ(readMission(out).frames.size(), 3u);
}

// Every file under `folder` with its content, by relative path.
std::map<std::string, std::string> contentsOf(const std::filesystem::path& folder) {
  std::map<std::string, std::string> contents;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
    const std::string name = std::filesystem::relative(entry.path(), folder).string();
    contents[name] = entry.is_regular_file() ? test::readText(entry.path()) : "(folder)";
  }
  return contents;
}

// Two runs into one folder used to both exit 0 and leave navigation, ground truth and frames
// of different runs mixed: a run holds its folder (a flock on it), and a second fails at once.
TEST(CliSimulate, ASecondRunIntoAFolderInUseFailsAndLeavesItAsItWas) {
  test::ScratchDir dir;
  const auto out = dir.path() / "riser";
  ASSERT_EQ(runCli("simulate --scene riser --max-frames 2 --seed 4 --out " + quoted(out)).exit_code,
            0);
  const auto before = contentsOf(out);
  {
    // Held as a running sonarcarve holds it.
    const int held = ::open(out.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    ASSERT_GE(held, 0);
    ASSERT_EQ(::flock(held, LOCK_EX | LOCK_NB), 0);
    const auto second =
        runCli("simulate --scene riser --max-frames 1 --seed 9 --force --out " + quoted(out));
    ::close(held);
    EXPECT_EQ(second.exit_code, 1) << second.output;
    EXPECT_NE(
        second.output.find(out.string() + ": is being written by another sonarcarve run (pid " +
                           std::to_string(::getpid()) + ")"),
        std::string::npos)
        << second.output;
    EXPECT_EQ(contentsOf(out), before);
  }
  // Released: the run goes ahead, and the lock has left no file in the folder.
  const auto third =
      runCli("simulate --scene riser --max-frames 1 --seed 9 --force --out " + quoted(out));
  ASSERT_EQ(third.exit_code, 0) << third.output;
  EXPECT_EQ(readMission(out).frames.size(), 1u);
  for (const auto& [name, content] : contentsOf(out)) {
    EXPECT_TRUE(before.count(name)) << name << " was not there after the first run";
  }
}

// A FIFO or a device as --out is refused before any work, and left as it was.
TEST(CliSimulate, AnOutThatIsNotAFolderIsRefused) {
  test::ScratchDir dir;
  const auto fifo = dir.path() / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const auto r = runCli("simulate --scene riser --max-frames 1 --out " + quoted(fifo));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("fifo: is a FIFO (named pipe): expected a folder or a new path"),
            std::string::npos)
      << r.output;
  EXPECT_TRUE(std::filesystem::is_fifo(fifo));
}

TEST(CliSimulate, ClippedBeamIsRecordedInTheSettings) {
  test::ScratchDir dir;
  const auto out = dir.path() / "riser";
  const auto r =
      runCli("simulate --scene riser --max-frames 2 --beam clipped --out " + quoted(out));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(readMission(out).frames.size(), 2u);
  const std::string settings = test::readText(out / "simulation.yaml");
  EXPECT_NE(settings.find("beam: clipped"), std::string::npos) << settings;
  // The seed paper's beam: traced over +-aperture/2 only.
  EXPECT_DOUBLE_EQ(settingValue(settings, "traced_elevation_deg"), 10.0) << settings;
  const auto bad = runCli("simulate --scene riser --beam fuzzy --out " + quoted(dir.path() / "b"));
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.output.find("--beam"), std::string::npos) << bad.output;
}

TEST(CliSimulate, SimulatedAndDeclaredElevationBeamsAreSetApart) {
  test::ScratchDir dir;
  const auto out = dir.path() / "riser";
  const auto r = runCli(
      "simulate --scene riser --max-frames 1 --elevation-beam gaussian --declared-beam clipped "
      "--out " +
      quoted(out));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // The mission declares the clipped beam; the frames were made with a Gaussian, traced to
  // -30 dB (sqrt(10) times aperture/2).
  EXPECT_EQ(readMission(out).sonar.elevationBeam(), ElevationBeam::Clipped);
  const std::string settings = test::readText(out / "simulation.yaml");
  EXPECT_NE(settings.find("beam: realistic\n"), std::string::npos) << settings;
  EXPECT_NE(settings.find("elevation_beam: gaussian\n"), std::string::npos) << settings;
  EXPECT_NE(settings.find("declared_beam: clipped\n"), std::string::npos) << settings;
  EXPECT_NEAR(settingValue(settings, "traced_elevation_deg"), 31.62, 0.01) << settings;

  // A table: its file recorded; a bad one refused naming its line.
  const auto table = dir.path() / "beam.csv";
  test::writeText(table, "elevation_deg,gain_db\n-15,-12\n0,0\n15,-12\n");
  const auto t =
      runCli("simulate --scene riser --max-frames 1 --elevation-beam table:" + quoted(table) +
             " --out " + quoted(dir.path() / "t"));
  ASSERT_EQ(t.exit_code, 0) << t.output;
  EXPECT_EQ(readMission(dir.path() / "t").sonar.elevationBeam(), ElevationBeam::MainLobe);
  const std::string table_settings = test::readText(dir.path() / "t" / "simulation.yaml");
  EXPECT_NE(table_settings.find("elevation_beam: table\n"), std::string::npos) << table_settings;
  EXPECT_NE(table_settings.find("elevation_beam_table: \"" + table.string() + "\""),
            std::string::npos)
      << table_settings;
  EXPECT_NE(table_settings.find("declared_beam: sinc\n"), std::string::npos) << table_settings;
  test::writeText(table, "-15,-12\n15,-12\n0,0\n");
  const auto unsorted = runCli("simulate --scene riser --elevation-beam table:" + quoted(table) +
                               " --out " + quoted(dir.path() / "u"));
  EXPECT_NE(unsorted.exit_code, 0);
  EXPECT_NE(unsorted.output.find("line 3"), std::string::npos) << unsorted.output;
  EXPECT_NE(unsorted.output.find("sorted"), std::string::npos) << unsorted.output;
  // The clipped beam keeps the seed paper's pattern.
  const auto clipped = runCli(
      "simulate --scene riser --beam clipped --elevation-beam truncated "
      "--out " +
      quoted(dir.path() / "c"));
  EXPECT_NE(clipped.exit_code, 0);
  EXPECT_NE(clipped.output.find("--beam realistic"), std::string::npos) << clipped.output;
}

TEST(CliSimulate, CoherentNoiseAndSpreadingLossAreRecordedInTheSettings) {
  test::ScratchDir dir;
  const auto out = dir.path() / "riser";
  const auto r = runCli(
      "simulate --scene riser --max-frames 1 --noise coherent --spreading-loss 2 "
      "--tvg 1 --out " +
      quoted(out));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string settings = test::readText(out / "simulation.yaml");
  EXPECT_NE(settings.find("combination: coherent"), std::string::npos) << settings;
  EXPECT_DOUBLE_EQ(settingValue(settings, "spreading_exponent"), 2.0) << settings;
  EXPECT_DOUBLE_EQ(settingValue(settings, "tvg_exponent"), 1.0) << settings;
  const auto bad =
      runCli("simulate --scene riser --spreading-loss -1 --out " + quoted(dir.path() / "b"));
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.output.find("--spreading-loss"), std::string::npos) << bad.output;
}

// `--intensity decibel` stores bytes of 80/255 dB, as an ARIS does. Read back, a frame is its
// linear twin's power (the same seed draws the same image) within what the two roundings
// allow: half a byte (40/255 dB) on the decibel side, half a count on the linear side.
TEST(CliSimulate, DecibelFramesHoldTheirLinearTwinsPowerWithinHalfAByte) {
  test::ScratchDir dir;
  for (const std::string scale : {"linear", "decibel"}) {
    const auto r = runCli("simulate --scene riser --max-frames 2 --seed 4 --intensity " + scale +
                          " --out " + quoted(dir.path() / scale));
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  const Mission decibel = readMission(dir.path() / "decibel");
  const Mission linear = readMission(dir.path() / "linear");
  EXPECT_EQ(decibel.sonar.intensityScale(), IntensityScale::decibel(80.0, 255.0));
  EXPECT_TRUE(linear.sonar.intensityScale().isLinear());
  const cv::Mat bytes =
      cv::imread((dir.path() / "decibel" / "frames" / "000001.png").string(), cv::IMREAD_UNCHANGED);
  double most_byte = 0.0;
  cv::minMaxLoc(bytes, nullptr, &most_byte);
  EXPECT_LE(most_byte, 255.0);
  EXPECT_GT(most_byte, 100.0);  // the riser's returns, over 31 dB

  const cv::Mat p_db = loadFrame(decibel, 1).image;
  const cv::Mat p_lin = loadFrame(linear, 1).image;
  const double half_byte = std::pow(10.0, 4.0 / 255.0);  // 10^(40/255 dB / 10)
  int compared = 0;
  for (int r = 0; r < p_lin.rows; ++r) {
    for (int c = 0; c < p_lin.cols; ++c) {
      const double lin = p_lin.at<float>(r, c);
      const double db = p_db.at<float>(r, c);
      if (lin <= 1.0) {  // under 1.5 before rounding: byte 0 to 6
        ASSERT_LE(db, 1.5 * half_byte) << r << ", " << c;
        continue;
      }
      const double slack = 0.5 / lin + 1e-5;
      ASSERT_GE(db / lin, (1.0 - slack) / half_byte) << r << ", " << c << ": " << lin;
      ASSERT_LE(db / lin, (1.0 + slack) * half_byte) << r << ", " << c << ": " << lin;
      ++compared;
    }
  }
  EXPECT_GT(compared, p_lin.rows * p_lin.cols / 2);  // the noisy background, mostly

  const auto info = runCli("info " + quoted(dir.path() / "decibel"));
  EXPECT_NE(info.output.find("intensity  decibel (255 counts = 80 dB)"), std::string::npos)
      << info.output;
  // A run's keep level is power read from the bytes, and says so; a linear sonar's, counts.
  for (const std::string scale : {"linear", "decibel"}) {
    const auto run = runCli("reconstruct " + quoted(dir.path() / scale) + " --verbose --out " +
                            quoted(dir.path() / (scale + "_run")));
    ASSERT_EQ(run.exit_code, 0) << run.output;
    const std::string unit = scale == "linear" ? "counts" : "power";
    EXPECT_NE(run.output.find(" " + unit + " on the beam's axis"), std::string::npos) << run.output;
  }
}

// `--horizontal-beam-width` beams (1 degree over 0.2 degree spacing) blur the riser across
// bearing; the mission says how wide they are, and the engine's deblurring takes the blur out:
// the energy the wide beams put where the narrow-beam twin (same seed) images nothing falls to
// under a quarter, and the frame keeps its energy (within 1 %: the residue under half a count
// is set dark).
TEST(CliSimulate, WideBeamsAreDeclaredAndTheirBlurTakenOut) {
  test::ScratchDir dir;
  for (const std::string width : {"0", "1"}) {
    const auto r = runCli(
        "simulate --scene riser --max-frames 6 --noise none --seed 4 "
        "--horizontal-beam-width " +
        width + " --out " + quoted(dir.path() / width));
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  const Mission narrow = readMission(dir.path() / "0");
  const Mission wide = readMission(dir.path() / "1");
  EXPECT_EQ(narrow.sonar.horizontalBeamWidth(), 0.0);
  EXPECT_NEAR(wide.sonar.horizontalBeamWidth(), degToRad(1.0), 1e-12);
  ASSERT_TRUE(BearingDeblur(wide.sonar).active());
  const cv::Mat twin = loadFrame(narrow, 1).image;
  const cv::Mat blurred = loadFrame(wide, 1).image;
  // The frames as the engine reads them (no noise: no detector).
  const cv::Mat sharp = DenoisedFrames(wide, wide.sonar, NoiseChoice{}).load(1).image;
  // Whole counts cannot show under half a count: the deconvolution's residue there is dark.
  EXPECT_EQ(cv::countNonZero((sharp > 0.0f) & (sharp < 0.5f)), 0);
  const cv::Mat nothing = twin < 0.5f;
  const auto haloShare = [&](const cv::Mat& image) {
    cv::Mat halo = image.clone();
    halo.setTo(0.0f, ~nothing);
    return cv::sum(halo)[0] / cv::sum(image)[0];
  };
  EXPECT_NEAR(cv::sum(sharp)[0], cv::sum(blurred)[0], 1e-2 * cv::sum(blurred)[0]);
  const double before = haloShare(blurred);
  const double after = haloShare(sharp);
  EXPECT_GT(before, 0.01);
  EXPECT_LT(after, 0.25 * before) << before;
  // A log that does not say how wide its beams are: the width is read from its frames, to
  // the cutoff's bin and the 1 % search (unit/beam_width_estimate_test.cpp), and none is read
  // from the narrow twin's.
  SilentProgress progress;
  const std::vector<std::size_t> all{0, 1, 2, 3, 4, 5};
  const SonarModel unsaid = wide.sonar.withHorizontalBeamWidth(0.0);
  const BeamWidthChoice read = chooseBeamWidth(wide, unsaid, all, progress);
  EXPECT_NEAR(radToDeg(read.sonar.horizontalBeamWidth()), 1.0, 0.05) << read.reason;
  EXPECT_NE(read.reason.find("width read from 6 frames"), std::string::npos) << read.reason;
  const BeamWidthChoice none = chooseBeamWidth(narrow, narrow.sonar, all, progress);
  EXPECT_EQ(none.sonar.horizontalBeamWidth(), 0.0);
  EXPECT_NE(none.reason.find("none was read from 6 frames"), std::string::npos) << none.reason;
  // A declared width is used as it is.
  EXPECT_EQ(chooseBeamWidth(wide, wide.sonar, all, progress).reason, "");
  // `info` on the wide mission with its width taken out says what a run reads.
  const auto yaml = dir.path() / "1" / "mission.yaml";
  std::string text = test::readText(yaml);
  const auto key = text.find("  horizontal_beam_width_deg");
  ASSERT_NE(key, std::string::npos);
  text.erase(key, text.find('\n', key) + 1 - key);
  test::writeText(yaml, text);
  const auto info = runCli("info --json " + quoted(dir.path() / "1"));
  ASSERT_EQ(info.exit_code, 0) << info.output;
  const nlohmann::json j = nlohmann::json::parse(info.output);
  EXPECT_TRUE(j["sonar"]["horizontal_beam_width_deg"].is_null());
  EXPECT_NEAR(j["beam_width"]["read_deg"].get<double>(), 1.0, 0.05);
  EXPECT_NE(j["beam_width"]["reading"].get<std::string>().find("width read from 6 frames"),
            std::string::npos);
}

TEST(CliSimulate, WideBeamsNoiseIsFormedByTheBeamsAndTheirWidthReadThroughIt) {
  // Speckle and background correlated across bearing as the beams overlap
  // (unit/sim_noise_test.cpp) keep the rows' cutoff: the width is read through the noise. The
  // envelope's detection spreads a little power past the cutoff and moves its steepest fall
  // down by up to a smoothing window (11 of 650 bins, 10 % of a 1 degree beam's cutoff), so
  // the width is read up to 20 % wide.
  test::ScratchDir dir;
  const auto r =
      runCli("simulate --scene riser --max-frames 3 --seed 4 --horizontal-beam-width 1 --out " +
             quoted(dir.path()));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Mission noisy = readMission(dir.path());
  SilentProgress progress;
  const BeamWidthChoice read =
      chooseBeamWidth(noisy, noisy.sonar.withHorizontalBeamWidth(0.0), {0, 1, 2}, progress);
  EXPECT_GE(radToDeg(read.sonar.horizontalBeamWidth()), 0.95) << read.reason;
  EXPECT_LE(radToDeg(read.sonar.horizontalBeamWidth()), 1.2) << read.reason;
}

TEST(CliNavError, WritesTheMissionsNavigationWithSeededErrors) {
  // The example mission's navigation, with a constant bias of 0.5 m (standard deviation per
  // axis) and no other error: every sample moves by the same offset, the same for one seed.
  test::ScratchDir dir;
  const auto nav = dir.path() / "nav.csv";
  const std::string command = "nav-error " + quoted(test::exampleMission()) + " --out " +
                              quoted(nav) + " --nav-bias-position 0.5 --seed 9";
  ASSERT_EQ(runCli(command).exit_code, 0);
  const Mission mission = readMission(test::exampleMission());
  const NavTrack recorded = readNavCsv(nav);
  ASSERT_EQ(recorded.samples().size(), mission.nav.samples().size());
  const Eigen::Vector3d offset =
      recorded.samples().front().position_m - mission.nav.samples().front().position_m;
  EXPECT_GT(offset.norm(), 1e-3);
  for (std::size_t i = 0; i < recorded.samples().size(); ++i) {
    const Eigen::Vector3d d =
        recorded.samples()[i].position_m - mission.nav.samples()[i].position_m;
    EXPECT_LT((d - offset).norm(), 1e-9) << i;
    EXPECT_EQ(recorded.samples()[i].time_s, mission.nav.samples()[i].time_s);
  }
  const auto again = dir.path() / "again.csv";
  ASSERT_EQ(runCli("nav-error " + quoted(test::exampleMission()) + " --out " + quoted(again) +
                   " --nav-bias-position 0.5 --seed 9")
                .exit_code,
            0);
  EXPECT_EQ(test::readText(again), test::readText(nav));  // reproducible
  EXPECT_NE(runCli("nav-error " + quoted(test::exampleMission()) + " --out " + quoted(again) +
                   " --nav-noise-position -1")
                .exit_code,
            0);
}

TEST(CliReconstruct, PoseRefinementWritesTheRefinedTrackAndReportsItsError) {
  // A drifting track (ground truth kept beside it): the refined track is written with the
  // navigation's columns, one pose per frame, and the report compares both with the truth.
  test::ScratchDir dir;
  const auto mission = dir.path() / "riser";
  ASSERT_EQ(runCli("simulate --scene riser --noise none --max-frames 30 --seed 5 "
                   "--nav-error-position 0.005 --nav-error-attitude 0.05 --out " +
                   quoted(mission))
                .exit_code,
            0);
  const auto out = dir.path() / "out";
  const auto on = runCli("reconstruct " + quoted(mission) + " --out " + quoted(out) +
                         " --mesh false --pose-refinement true");
  ASSERT_EQ(on.exit_code, 0) << on.output;
  const NavTrack refined = readNavCsv(out / "refined_nav.csv");
  const Mission m = readMission(mission);
  ASSERT_EQ(refined.samples().size(), m.frames.size());
  for (std::size_t i = 0; i < m.frames.size(); ++i) {
    EXPECT_EQ(refined.samples()[i].time_s, m.frames[i].time_s);
  }
  const std::string report = test::readText(out / "report.json");
  for (const char* key : {"\"pose_refinement\"", "\"per_frame\"", "\"track_error\"",
                          "\"navigation\"", "\"refined\"", "\"rms_position_m\""}) {
    EXPECT_NE(report.find(key), std::string::npos) << key;
  }
  // Off again, into the same folder: no refined track of the earlier run is left behind.
  const auto off = runCli("reconstruct " + quoted(mission) + " --out " + quoted(out) +
                          " --mesh false --pose-refinement false");
  ASSERT_EQ(off.exit_code, 0) << off.output;
  EXPECT_FALSE(std::filesystem::exists(out / "refined_nav.csv"));
  EXPECT_EQ(test::readText(out / "report.json").find("\"pose_refinement\""), std::string::npos);
}

// A seabed relief under the riser: recorded in the settings, and in the ground truth the seabed
// rises and falls away from the riser (beyond its cables, which end 6 m from it) while it stays
// levelled where the riser stands.
TEST(CliSimulate, SeabedReliefIsRecordedAndShapesTheGroundTruth) {
  test::ScratchDir dir;
  const auto out = dir.path() / "riser";
  const auto r =
      runCli("simulate --scene riser --seabed-relief 0.3 --max-frames 2 --out " + quoted(out));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string settings = test::readText(out / "simulation.yaml");
  ASSERT_NE(settings.find("seabed_relief:"), std::string::npos) << settings;
  EXPECT_DOUBLE_EQ(settingValue(settings, "relief_m"), 0.3) << settings;
  EXPECT_DOUBLE_EQ(settingValue(settings, "wavelength_m"), 6.0) << settings;
  float lo = INFINITY;
  float hi = -INFINITY;
  for (const Eigen::Vector3f& p : readPlyMesh(out / "ground_truth.ply").vertices.positions) {
    if (p.head<2>().cwiseAbs().maxCoeff() > 6.5f) {  // only the seabed out there
      lo = std::min(lo, p.z());
      hi = std::max(hi, p.z());
    } else if (p.head<2>().norm() < 1.0f && p.z() > 19.0f) {  // the seabed and the riser's foot
      EXPECT_FLOAT_EQ(p.z(), 20.0f) << p.transpose();
    }
  }
  EXPECT_GT(hi - lo, 0.2f) << lo << " to " << hi;
  EXPECT_LT(hi - lo, 1.2f) << lo << " to " << hi;  // within twice the amplitude of 20 m

  // The seabed field has a relief of its own.
  const auto field = runCli("simulate --scene seabed-field --seabed-relief 0.3 --out " +
                            quoted(dir.path() / "field"));
  EXPECT_NE(field.exit_code, 0);
  EXPECT_NE(field.output.find("--seabed-relief"), std::string::npos) << field.output;
}

TEST(CliSimulate, BadSceneOrTrajectoryFailsWithAMessage) {
  test::ScratchDir dir;
  const auto out = quoted(dir.path() / "m");
  const auto scene = runCli("simulate --scene nowhere.stl --out " + out);
  EXPECT_NE(scene.exit_code, 0);
  EXPECT_NE(scene.output.find("nowhere.stl"), std::string::npos) << scene.output;
  const auto traj = runCli("simulate --scene riser --trajectory zigzag --out " + out);
  EXPECT_NE(traj.exit_code, 0);
  EXPECT_NE(traj.output.find("unknown trajectory"), std::string::npos) << traj.output;
}

TEST(CliFrame, DrawsPolarAndFanPictures) {
  test::ScratchDir dir;
  const auto polar = dir.path() / "polar.png";
  const auto fan = dir.path() / "fan.png";
  const auto r = runCli("frame " + quoted(test::exampleMission()) + " --index 2 --polar " +
                        quoted(polar) + " --fan " + quoted(fan));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const cv::Mat p = cv::imread(polar.string());
  EXPECT_EQ(p.cols, 64);
  EXPECT_EQ(p.rows, 200);
  const cv::Mat f = cv::imread(fan.string());
  EXPECT_EQ(f.cols, 900);
  EXPECT_GT(f.rows, 100);
  EXPECT_NE(runCli("frame " + quoted(test::exampleMission()) + " --index 99").exit_code, 0);
  // A negative index is refused as such, not read as 18446744073709551615 (issue 44).
  const auto negative = runCli("frame " + quoted(test::exampleMission()) + " --index -1");
  EXPECT_NE(negative.exit_code, 0);
  EXPECT_NE(negative.output.find("--index"), std::string::npos) << negative.output;
  EXPECT_EQ(negative.output.find("18446744073709551615"), std::string::npos) << negative.output;
}

}  // namespace
}  // namespace sonarcarve

namespace sonarcarve {
namespace {

// Ctrl-C as a user presses it: SIGINT to a running simulate stops it after the current frame,
// with a valid mission of the frames done and exit code 130.
TEST(CliSimulate, CtrlCStopsCleanlyWithAValidShorterMission) {
  test::ScratchDir dir;
  const auto out = dir.path() / "riser";
  const auto script = dir.path() / "interrupt.sh";
  test::writeText(script, std::string("'") + SONARCARVE_CLI + "' simulate --scene riser --out " +
                              test::quoted(out) +
                              " > /dev/null 2>&1 &\npid=$!\n"
                              // Interrupt once the third frame is on disk (at most 20 s),
                              // in the folder the mission is written in first.
                              "for i in $(seq 400); do ls " +
                              test::quoted(out) +
                              "/.run.tmp-*/frames/000002.png > /dev/null 2>&1 && break; sleep "
                              "0.05; done\nkill -INT $pid\nwait $pid\n");
  const int status = std::system(("bash " + test::quoted(script)).c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  const Mission mission = readMission(out);
  EXPECT_GT(mission.frames.size(), 0u);
  EXPECT_LT(mission.frames.size(), 98u);  // the whole inspection has 98 frames
  EXPECT_TRUE(checkFrames(mission).empty());
}

}  // namespace
}  // namespace sonarcarve
