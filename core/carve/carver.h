// Carver: the interface every carving engine implements, and the factory that makes one from
// its key. The pipeline, the CLI and the GUI see engines only through this header.
//
// An engine integrates denoised polar frames (CV_32F) seen from known poses into a voxel map
// on the global grid of VoxelMap (voxel (i, j, k) covers [i, i+1) * voxel size, NED), and
// answers what a voxel holds: kUnknown (never observed), 0 (carved: empty water) or a
// positive value (occupied). Engines register themselves with registerCarverEngine() from
// their own source file; adding one is one file and one registration line (docs/architecture.md).
#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "carve/carve_params.h"
#include "carve/seabed_model.h"
#include "common/thread_pool.h"
#include "sonar/sonar_model.h"

namespace sonarcarve {

class VoxelMap;

/// The engines. A value not listed here may be registered by code outside core (tests).
enum class CarverEngine : int {
  Fast = 0,       ///< voxel-centric, block-sparse, multi-threaded (FastCarver)
  Reference = 1,  ///< the paper's arcs into an OctoMap octree, single-threaded (ReferenceCarver)
};

/// For occlusion-aware carving: the range of the first surface in each (beam, elevation bin)
/// cell of a frame (OcclusionResolver::firstReturnRanges). A voxel farther than that range
/// plus `margin_m` is hidden behind the surface: the frame did not observe it and leaves it.
struct VisibilityLimit {
  const std::vector<float>* first_return_m = nullptr;
  int elevation_bins = 1;
  double elevation_step_rad = 0.0;
  double margin_m = 0.0;
  /// Bin 0 starts this far under the sonar's axis; 0: at the aperture's lower edge.
  double half_elevation_rad = 0.0;
};

/// Elevation bins of equal width, at most `max_step_rad`, over +-`half_elevation_rad`.
inline int visibilityBins(double half_elevation_rad, double max_step_rad) {
  return std::max(1, static_cast<int>(std::ceil(2.0 * half_elevation_rad / max_step_rad)));
}

/// The margin behind a surface that stays observed: its voxel (the half diagonal either way)
/// and the pixel's range bin.
inline double surfaceMargin(double voxel_size_m, double range_resolution_m) {
  return std::sqrt(3.0) * voxel_size_m + range_resolution_m;
}

/// What an engine holds, for reports and memory budgets.
struct CarverStats {
  std::size_t occupied_voxels = 0;
  std::size_t memory_bytes = 0;
  std::size_t seabed_frames = 0;  ///< seabed-aware carving: frames a seabed explained
};

class Carver {
 public:
  using VoxelVisitor = std::function<void(const Eigen::Vector3i& voxel, float value)>;

  virtual ~Carver() = default;
  /// Carves one frame (CV_32F, the sonar's rows x cols) seen from `T_world_sonar`. `stamp`
  /// grows with every frame (the frame number + 1). Throws Error if the image does not match
  /// the sonar. `visibility` is honoured only where supportsVisibilityLimit(). `before`: the
  /// frame before its detector, where one ran with a noise model (seabed-aware carving fits
  /// the seabed to it; engines may ignore it).
  virtual void integrate(const cv::Mat& image, const Eigen::Isometry3d& T_world_sonar,
                         std::uint32_t stamp, const VisibilityLimit& visibility = {},
                         const BeforeDetection* before = nullptr) = 0;
  virtual bool supportsVisibilityLimit() const { return false; }
  /// The value of global voxel `voxel`: VoxelMap::kUnknown if never observed.
  virtual float value(const Eigen::Vector3i& voxel) const = 0;
  /// Every occupied voxel that can be a first return: at least one of its six face
  /// neighbours is not occupied (voxels buried inside occupied space are behind one).
  virtual void forEachSurfaceCandidate(const VoxelVisitor& visit) const = 0;
  virtual CarverStats stats() const = 0;
  /// stats().memory_bytes without counting the voxels: engines answer it at once, so that a
  /// run can check its memory budget after every frame (pipeline/memory_budget.h).
  virtual std::size_t memoryBytes() const { return stats().memory_bytes; }
  /// The map as blocks with change stamps, for viewers' incremental updates and the OctoMap
  /// export; nullptr for engines that do not keep one.
  virtual const VoxelMap* blockMap() const { return nullptr; }
  /// The same map, for a run that releases its finished pages (eviction); null otherwise.
  virtual VoxelMap* evictableMap() { return nullptr; }
  /// Starts from a map carved before (reconstruct --load-map): fuses it by the voxel-wise
  /// minimum where it lies inside this map's box. Throws Error for engines that keep no
  /// block map.
  virtual void fuse(const VoxelMap& earlier);
};

/// Voxels and their values as two parallel arrays (what OcclusionResolver takes).
struct VoxelValues {
  std::vector<Eigen::Vector3i> voxels;
  std::vector<float> values;
};
/// Collects what `each` visits (e.g. a map's forEachOccupiedOnShell).
VoxelValues collectVoxels(const std::function<void(const Carver::VoxelVisitor&)>& each);
/// An engine's surface candidates.
VoxelValues surfaceCandidates(const Carver& carver);

/// What an engine is made from. `params.region` is the box the map must cover (set).
struct CarverSetup {
  const SonarModel& sonar;  ///< must outlive the engine
  CarveParams params;
  ThreadPool& pool;
};

using CarverFactory = std::function<std::unique_ptr<Carver>(const CarverSetup&)>;

/// Registers an engine under `key` and `name` (the word used in YAML and on the command line).
/// Returns true, so that a source file can register with one line at namespace scope:
///   const bool registered = registerCarverEngine(CarverEngine::Fast, "fast", makeFast);
/// Throws std::logic_error if the key or the name is taken.
bool registerCarverEngine(CarverEngine key, std::string name, CarverFactory factory);

/// Makes the engine registered under `key`. Throws Error naming the engine if there is none
/// or if the setup does not suit it.
std::unique_ptr<Carver> makeCarver(CarverEngine key, const CarverSetup& setup);

/// Registered engines, in key order.
std::vector<CarverEngine> carverEngines();
std::string carverEngineName(CarverEngine key);
std::optional<CarverEngine> carverEngineFromName(std::string_view name);

}  // namespace sonarcarve
