// The fast engine behind the Carver interface: a VoxelMap over the setup's region, carved by
// FastCarver on the setup's pool.
#include "carve/carver.h"
#include "carve/fast_carver.h"
#include "carve/map_file.h"
#include "carve/voxel_map.h"

namespace sonarcarve {
namespace {

class FastEngine final : public Carver {
 public:
  explicit FastEngine(const CarverSetup& setup)
      : map_(setup.params.voxel_size_m, *setup.params.region, keepsViewCounts(setup.params)),
        carver_(map_, setup.sonar, setup.params, setup.pool) {}

  void integrate(const cv::Mat& image, const Eigen::Isometry3d& T_world_sonar, std::uint32_t stamp,
                 const VisibilityLimit& visibility, const BeforeDetection* before) override {
    carver_.integrate(image, T_world_sonar, stamp, visibility, before);
  }
  bool supportsVisibilityLimit() const override { return true; }
  float value(const Eigen::Vector3i& voxel) const override { return map_.value(voxel); }
  void forEachSurfaceCandidate(const VoxelVisitor& visit) const override {
    map_.forEachOccupiedOnShell(visit);
  }
  CarverStats stats() const override {
    return {map_.occupiedCount(), map_.memoryBytes(), carver_.seabedFrames()};
  }
  std::size_t memoryBytes() const override { return map_.memoryBytes(); }
  const VoxelMap* blockMap() const override { return &map_; }
  VoxelMap* evictableMap() override { return &map_; }
  void fuse(const VoxelMap& earlier) override { fuseInto(map_, earlier); }

 private:
  VoxelMap map_;
  FastCarver carver_;
};

[[maybe_unused]] const bool registered = registerCarverEngine(
    CarverEngine::Fast, "fast", [](const CarverSetup& setup) -> std::unique_ptr<Carver> {
      return std::make_unique<FastEngine>(setup);
    });

}  // namespace
}  // namespace sonarcarve
