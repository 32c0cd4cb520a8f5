#include "support/test_support.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <tuple>

#include "common/angles.h"

namespace sonarcarve::test {

ScratchDir::ScratchDir() {
  std::random_device rd;
  path_ = std::filesystem::temp_directory_path() /
          ("sonarcarve-test-" + std::to_string(rd()) + std::to_string(rd()));
  std::filesystem::create_directories(path_);
}

ScratchDir::~ScratchDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

std::filesystem::path testData(const std::string& relative) {
  return std::filesystem::path(SONARCARVE_TEST_DATA_DIR) / relative;
}

std::filesystem::path exampleMission() {
  return std::filesystem::path(SONARCARVE_RESOURCE_DIR) / "example_mission";
}

std::filesystem::path copyExampleMission(const std::filesystem::path& dir,
                                         const std::string& name) {
  const auto target = dir / name;
  std::filesystem::copy(exampleMission(), target, std::filesystem::copy_options::recursive);
  return target;
}

SonarModel paperSonar() {
  return SonarModel("paper", RangeBins{0.0, 0.02, 500}, BearingTable::uniform(degToRad(130), 650),
                    degToRad(20));
}

SurfacePoints sphereShellPoints(const Eigen::Vector3f& centre, float radius_m, float voxel_m,
                                int rings) {
  SurfacePoints points;
  std::set<std::tuple<int, int, int>> seen;
  for (int i = 0; i < rings; ++i) {
    const double polar = M_PI * (i + 0.5) / rings;
    const int around = std::max(1, static_cast<int>(2 * rings * std::sin(polar)));
    for (int j = 0; j < around; ++j) {
      const double azimuth = 2 * M_PI * j / around;
      const Eigen::Vector3f d(static_cast<float>(std::sin(polar) * std::cos(azimuth)),
                              static_cast<float>(std::sin(polar) * std::sin(azimuth)),
                              static_cast<float>(std::cos(polar)));
      const Eigen::Vector3i v = ((centre + radius_m * d) / voxel_m).array().floor().cast<int>();
      if (seen.insert({v.x(), v.y(), v.z()}).second) {
        points.push_back({(v.cast<float>() + Eigen::Vector3f::Constant(0.5f)) * voxel_m,
                          100.0f + static_cast<float>(i), 7});
      }
    }
  }
  return points;
}

ImagingSettings clippedBeam() {
  ImagingSettings settings;
  settings.beam = SimulatedBeam::Clipped;
  return settings;
}

SonarModel nonUniformSonar() {
  std::vector<double> centres;
  for (int j = 0; j < 256; ++j) {
    const double u = -1.0 + 2.0 * (j + 0.5) / 256.0;  // (-1, 1)
    centres.push_back(std::asin(u * std::sin(degToRad(30))));
  }
  return SonarModel("nonuniform", RangeBins{0.1, 0.0028421889710794315, 703},
                    BearingTable::fromCentres(centres), degToRad(20));
}

std::string readText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void writeText(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
}

void writeSparseFile(const std::filesystem::path& path, std::uint64_t bytes) {
  writeText(path, "");
  ASSERT_EQ(::truncate(path.c_str(), static_cast<off_t>(bytes)), 0) << path;
}

std::vector<Eigen::Vector3d> readAsciiPlyPoints(const std::filesystem::path& path,
                                                std::string* header) {
  std::ifstream in(path);
  std::string line;
  std::size_t count = 0;
  while (std::getline(in, line) && line != "end_header") {
    if (header != nullptr) {
      *header += line + "\n";
    }
    std::istringstream words(line);
    std::string keyword, element;
    if (words >> keyword >> element && keyword == "element" && element == "vertex") {
      words >> count;
    }
  }
  std::vector<Eigen::Vector3d> points(count);
  for (std::size_t i = 0; i < count && std::getline(in, line); ++i) {
    std::istringstream(line) >> points[i].x() >> points[i].y() >> points[i].z();
  }
  return points;
}

}  // namespace sonarcarve::test

namespace sonarcarve::test {

void copyMissionWithoutTruth(const std::filesystem::path& from, const std::filesystem::path& to) {
  std::filesystem::copy(from, to, std::filesystem::copy_options::recursive);
  for (const char* truth : {"ground_truth.ply", "visible_points.ply", "ground_truth_poses.csv"}) {
    std::filesystem::remove(to / truth);
  }
}

}  // namespace sonarcarve::test
