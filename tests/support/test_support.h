// Helpers shared by the tests: scratch folders, the example mission, small sonar models.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "common/error.h"
#include "occlusion/surface_points.h"

#include "sim/sonar_simulator.h"
#include "sonar/sonar_model.h"

namespace sonarcarve::test {

/// A fresh empty folder under the system temp dir, removed when the object dies.
class ScratchDir {
 public:
  ScratchDir();
  ~ScratchDir();
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

/// A sphere's surface as carving gives it: the centres of the `voxel_m` voxels it crosses,
/// sampled on `rings` rings of latitude; each point's intensity is 100 + its ring, views 7.
SurfacePoints sphereShellPoints(const Eigen::Vector3f& centre, float radius_m, float voxel_m,
                                int rings);

/// A file under tests/data/ (fixtures kept in the repository).
std::filesystem::path testData(const std::string& relative);
/// The example mission shipped in resources/.
std::filesystem::path exampleMission();
/// Copies the example mission into `dir`/name and returns the copy's folder.
std::filesystem::path copyExampleMission(const std::filesystem::path& dir,
                                         const std::string& name = "mission");

/// The seed paper's sonar: 2 cm bins to 10 m, 130 deg in 650 beams, 20 deg aperture.
SonarModel paperSonar();
/// Imaging with the seed paper's clipped beam (nothing outside +-aperture/2), for tests of the
/// engine against the paper's own model; the simulator's default is the realistic beam.
ImagingSettings clippedBeam();
/// A sonar with a non-uniform table, like the Oculus': 256 beams over +-30 deg, spaced
/// more finely at the centre.
SonarModel nonUniformSonar();

std::string readText(const std::filesystem::path& path);

/// `run` must throw a sonarcarve::Error whose text holds every fragment.
template <typename Run>
void expectError(Run run, const std::vector<std::string>& fragments) {
  try {
    run();
    ADD_FAILURE() << "no error; expected one with '" << fragments.front() << "'";
  } catch (const Error& e) {
    for (const auto& f : fragments) {
      EXPECT_NE(std::string(e.what()).find(f), std::string::npos)
          << "'" << f << "' not in: " << e.what();
    }
  }
}
void writeText(const std::filesystem::path& path, const std::string& text);
/// A copy of the simulated mission `from` at `to` without its ground truth files
/// (ground_truth.ply, visible_points.ply, ground_truth_poses.csv), which are in the frame of
/// `from`'s navigation: for twins whose navigation is given in another frame.
void copyMissionWithoutTruth(const std::filesystem::path& from, const std::filesystem::path& to);
/// A file of `bytes` that takes no disk (sparse, all zeros); fails the test if it cannot be.
void writeSparseFile(const std::filesystem::path& path, std::uint64_t bytes);
/// The x, y, z of an ASCII PLY's vertices, in double (a float reader would lose the metres'
/// decimals at 5e6 m); its header lines before end_header into `header` when given.
std::vector<Eigen::Vector3d> readAsciiPlyPoints(const std::filesystem::path& path,
                                                std::string* header = nullptr);

}  // namespace sonarcarve::test
