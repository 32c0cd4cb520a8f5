#include "pipeline/size_limits.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "common/angles.h"
#include "common/error.h"
#include "common/input_limits.h"

namespace sonarcarve {

namespace {

constexpr double kBlockTableBytes = 9.0;            // state, slot and stamp of a block
constexpr double kBlockContentBytes = 512.0 * 4.0;  // a Mixed block: 8^3 floats
constexpr double kSurfaceLayers = 2.0;              // blocks a surface straddles
constexpr double kOcclusionCellBytes = 8.0;
constexpr double kOcclusionBytesPerVoxel = 16.0 + 24.0 + 20.0;
// The occupancy mesh's peak was 1.6 kB a surface point on the noise-free riser (12,909 points,
// 20 MB) and 1.3 kB on a seabed (36,109 points, 45 MB): about twice that.
constexpr double kMeshBytesPerSurfacePoint = 3000.0;
constexpr double kMiB = 1024.0 * 1024.0;

double elevationSteps(const SonarModel& sonar, const CarveParams& carve) {
  return std::ceil(sonar.verticalAperture() / carve.elevation_step_rad);
}

std::string mib(double bytes) {
  std::ostringstream text;
  text.setf(std::ios::fixed);
  text.precision(0);
  text << std::ceil(bytes / kMiB) << " MiB";
  return text.str();
}

}  // namespace

MemoryEstimate estimateMemory(const Eigen::AlignedBox3d& bounds, const SonarModel& sonar,
                              const CarveParams& carve, unsigned threads) {
  const Eigen::Vector3d blocks = (bounds.sizes() / (carve.voxel_size_m * 8.0)).array().ceil() + 1.0;
  const double largest_face =
      std::max({blocks.x() * blocks.y(), blocks.y() * blocks.z(), blocks.x() * blocks.z()});
  MemoryEstimate e;
  e.map = blocks.prod() * kBlockTableBytes + kSurfaceLayers * largest_face * kBlockContentBytes;
  const double pixels = static_cast<double>(sonar.rows()) * sonar.cols();
  e.frames = threads * 2.0 * pixels * 4.0;
  e.occlusion = threads * elevationSteps(sonar, carve) * sonar.cols() * kOcclusionCellBytes;
  return e;
}

void requireMemory(const MemoryEstimate& e, const CarveParams& carve,
                   const std::optional<MemoryBudget>& budget) {
  if (!budget || e.total() <= static_cast<double>(budget->bytes)) {
    return;
  }
  std::string place = "voxel_size_m";
  std::string advice = "use a larger voxel size or a smaller region";
  if (e.occlusion > e.map && e.occlusion > e.frames) {
    place = "elevation_step_deg";
    advice = "use a larger elevation step";
  } else if (e.frames > e.map) {
    place = "frames";
    advice = "the sonar's frames (beams x range bins) are too large for this machine";
  }
  std::ostringstream text;
  text << "the reconstruction needs at least " << mib(e.total()) << " (map " << mib(e.map)
       << " at a voxel size of " << carve.voxel_size_m << " m, frames " << mib(e.frames)
       << ", occlusion buffers " << mib(e.occlusion) << " at an elevation step of "
       << radToDeg(carve.elevation_step_rad) << " degrees) but the memory budget is "
       << memoryFigure(static_cast<double>(budget->bytes)) << " (" << budget->origin
       << "): " << advice << ", or set memory_budget_mb";
  throw Error("parameters", place, text.str());
}

MemoryEstimate requireBoundedSizes(const Eigen::AlignedBox3d& bounds, const SonarModel& sonar,
                                   const CarveParams& carve, unsigned threads,
                                   const std::optional<MemoryBudget>& budget) {
  const Eigen::Vector3d extent_m = bounds.sizes();
  const Eigen::Vector3d per_axis = (extent_m / carve.voxel_size_m).array().ceil() + 1.0;
  const double voxels = per_axis.prod();
  if (!(voxels <= kMaxMapVoxels)) {
    std::ostringstream text;
    text.precision(3);
    text << "the map's box (" << extent_m.x() << " x " << extent_m.y() << " x " << extent_m.z()
         << " m) holds " << voxels << " voxels of " << carve.voxel_size_m << " m: expected at most "
         << kMaxMapVoxels << "; use a larger voxel size or a smaller region";
    throw Error("parameters", "voxel_size_m", text.str());
  }
  const double cells = elevationSteps(sonar, carve) * sonar.cols();
  if (!(cells <= static_cast<double>(kMaxFramePixels))) {
    std::ostringstream text;
    text << "a step of " << radToDeg(carve.elevation_step_rad) << " degrees over the "
         << radToDeg(sonar.verticalAperture()) << " degree aperture and " << sonar.cols()
         << " beams makes " << cells << " occlusion cells per frame: expected at most "
         << kMaxFramePixels << "; use a larger step";
    throw Error("parameters", "elevation_step_deg", text.str());
  }
  const MemoryEstimate estimate = estimateMemory(bounds, sonar, carve, threads);
  requireMemory(estimate, carve, budget);
  return estimate;
}

double occlusionStageBytes(std::size_t occupied_voxels) {
  return static_cast<double>(occupied_voxels) * kOcclusionBytesPerVoxel;
}

double meshStageBytes(std::size_t surface_points) {
  return static_cast<double>(surface_points) * kMeshBytesPerSurfacePoint;
}

}  // namespace sonarcarve
