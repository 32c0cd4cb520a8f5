// A toy engine added the way docs/architecture.md says: this one file and its registration
// line. It carves by brute force, every voxel of the region projected into every frame, so
// it doubles as a third, independent implementation of the carving semantics: the
// behavioural suite (carver_behaviour_test.cpp) runs over it like over the real engines.
#include <gtest/gtest.h>

#include <map>
#include <tuple>

#include "carve/carver.h"
#include "carve/voxel_map.h"
#include "common/error.h"

namespace sonarcarve {
namespace {

constexpr CarverEngine kToyEngine{100};

class ToyCarver final : public Carver {
 public:
  explicit ToyCarver(const CarverSetup& setup) : sonar_(setup.sonar), params_(setup.params) {
    const double v = params_.voxel_size_m;
    lo_ = (params_.region->min() / v).array().floor().cast<int>();
    hi_ = (params_.region->max() / v).array().ceil().cast<int>();
  }

  void integrate(const cv::Mat& image, const Eigen::Isometry3d& T_world_sonar, std::uint32_t,
                 const VisibilityLimit&, const BeforeDetection*) override {
    if (image.type() != CV_32F || image.rows != sonar_.rows() || image.cols != sonar_.cols()) {
      throw Error("toy engine", "frame", "image does not match the sonar model");
    }
    const Eigen::Isometry3d T_sonar_world = T_world_sonar.inverse();
    for (int z = lo_.z(); z < hi_.z(); ++z) {
      for (int y = lo_.y(); y < hi_.y(); ++y) {
        for (int x = lo_.x(); x < hi_.x(); ++x) {
          const Eigen::Vector3d centre =
              (Eigen::Vector3d(x, y, z) + Eigen::Vector3d::Constant(0.5)) * params_.voxel_size_m;
          const auto pixel = sonar_.pixelOf(T_sonar_world * centre);
          if (!pixel) {
            continue;
          }
          const float lit = image.at<float>(pixel->row, pixel->col);
          const float intensity = lit > params_.intensity_threshold ? lit : 0.0f;
          float& kept = voxels_.try_emplace({x, y, z}, VoxelMap::kUnknown).first->second;
          kept = std::min(kept, intensity);
        }
      }
    }
  }
  float value(const Eigen::Vector3i& v) const override {
    const auto it = voxels_.find({v.x(), v.y(), v.z()});
    return it == voxels_.end() ? VoxelMap::kUnknown : it->second;
  }
  void forEachSurfaceCandidate(const VoxelVisitor& visit) const override {
    const auto occupied = [&](const Eigen::Vector3i& v) {
      const float value = this->value(v);
      return value > 0.0f && value < VoxelMap::kUnknown;
    };
    for (const auto& [key, value] : voxels_) {
      const Eigen::Vector3i v(std::get<0>(key), std::get<1>(key), std::get<2>(key));
      if (!occupied(v)) {
        continue;
      }
      for (int axis = 0; axis < 3; ++axis) {
        const Eigen::Vector3i step = Eigen::Vector3i::Unit(axis);
        if (!occupied(v + step) || !occupied(v - step)) {
          visit(v, value);
          break;
        }
      }
    }
  }
  CarverStats stats() const override {
    CarverStats stats;
    for (const auto& entry : voxels_) {
      stats.occupied_voxels += entry.second > 0.0f && entry.second < VoxelMap::kUnknown ? 1 : 0;
    }
    stats.memory_bytes = voxels_.size() * (sizeof(float) + 3 * sizeof(int));
    return stats;
  }

 private:
  const SonarModel& sonar_;
  CarveParams params_;
  Eigen::Vector3i lo_, hi_;
  std::map<std::tuple<int, int, int>, float> voxels_;
};

// The registration line.
[[maybe_unused]] const bool registered = registerCarverEngine(
    kToyEngine, "toy", [](const CarverSetup& s) { return std::make_unique<ToyCarver>(s); });

TEST(ToyEngine, IsMadeByTheFactoryFromItsKeyAndName) {
  ASSERT_EQ(carverEngineFromName("toy"), kToyEngine);
  const SonarModel sonar("tiny", RangeBins{1.0, 0.04, 50}, BearingTable::uniform(0.2, 5), 0.2);
  ThreadPool pool(1);
  CarveParams params;
  params.region = Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  const auto carver = makeCarver(kToyEngine, CarverSetup{sonar, params, pool});
  EXPECT_NE(dynamic_cast<const ToyCarver*>(carver.get()), nullptr);
}

}  // namespace
}  // namespace sonarcarve
