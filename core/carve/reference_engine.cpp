// The paper-faithful reference engine behind the Carver interface. It keeps no block map, so
// viewers get no map while it carves, and it ignores visibility limits (it carves every arc).
#include <unordered_set>

#include "carve/carver.h"
#include "carve/occupancy_export.h"
#include "carve/reference_carver.h"
#include "common/error.h"

namespace sonarcarve {
namespace {

struct VoxelHash {
  std::size_t operator()(const Eigen::Vector3i& v) const {
    return (static_cast<std::size_t>(v.x()) * 73856093u) ^
           (static_cast<std::size_t>(v.y()) * 19349663u) ^
           (static_cast<std::size_t>(v.z()) * 83492791u);
  }
};

// The engine is an OctoMap octree: a voxel beyond its keys would be dropped without a word.
const CarveParams& requireWithinOctoMapKeys(const CarveParams& params) {
  if (params.region) {
    if (const auto problem = octoMapKeyProblem(*params.region, params.voxel_size_m)) {
      throw Error("reference engine", "",
                  *problem + ": expected a map within them (the fast engine has no such limit)");
    }
  }
  return params;
}

class ReferenceEngine final : public Carver {
 public:
  explicit ReferenceEngine(const CarverSetup& setup)
      : carver_(setup.sonar, requireWithinOctoMapKeys(setup.params)) {}

  void integrate(const cv::Mat& image, const Eigen::Isometry3d& T_world_sonar, std::uint32_t,
                 const VisibilityLimit&, const BeforeDetection*) override {
    carver_.integrate(image, T_world_sonar);
  }
  float value(const Eigen::Vector3i& voxel) const override { return carver_.value(voxel); }
  void forEachSurfaceCandidate(const VoxelVisitor& visit) const override {
    const std::vector<Eigen::Vector3i> occupied = carver_.occupiedVoxels();
    const std::unordered_set<Eigen::Vector3i, VoxelHash> set(occupied.begin(), occupied.end());
    static const Eigen::Vector3i kFaces[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                              {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    for (const Eigen::Vector3i& v : occupied) {
      for (const Eigen::Vector3i& face : kFaces) {
        if (set.count(v + face) == 0) {
          visit(v, carver_.value(v));
          break;
        }
      }
    }
  }
  CarverStats stats() const override {
    return {carver_.occupiedVoxels().size(), carver_.memoryBytes()};
  }
  std::size_t memoryBytes() const override { return carver_.memoryBytes(); }

 private:
  ReferenceCarver carver_;
};

[[maybe_unused]] const bool registered = registerCarverEngine(
    CarverEngine::Reference, "reference", [](const CarverSetup& setup) -> std::unique_ptr<Carver> {
      return std::make_unique<ReferenceEngine>(setup);
    });

}  // namespace
}  // namespace sonarcarve
