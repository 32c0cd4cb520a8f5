#include "carve/fast_carver.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <optional>

#include "carve/seabed_field_fit.h"
#include "carve/seabed_heightfield.h"
#include "carve/seabed_model.h"
#include "carve/shadow_limit.h"
#include "common/error.h"
#include "sonar/beam_pattern.h"

namespace sonarcarve {
namespace {

constexpr int kSide = VoxelMap::kBlockSide;

// What the voxel kernel reads of one frame: the thresholded image and the pose.
struct FrameView {
  const float* pixels;  // rows x cols, thresholded
  int cols;
  int rows;
  Eigen::Matrix3f R_sonar_world;
  Eigen::Vector3f t_sonar_world;
  // Occlusion-aware carving (null: every voxel in the frustum is observed).
  const float* first_return = nullptr;
  int elevation_bins = 1;
  float limit_half_elevation = 0.0f;  // bin 0 starts this far under the axis
  float inv_elevation_step = 0.0f;
  float margin = 0.0f;
  // Seabed-aware carving (same rays as first_return, which ends past the seabed): per pixel
  // what the seabed leaves of it, per ray where the seabed's band starts. A voxel in front of
  // it is bounded by what the seabed leaves of its pixel; a voxel in the band by the whole
  // pixel, and kept by a lit one.
  const float* unexplained = nullptr;
  const float* seabed_from = nullptr;
  const float* seabed_doubt_from = nullptr;
  // Beam-aware carving (CarveParams::beam_aware).
  bool beam_aware = false;
  bool dark_is_exact = false;
  float dark_level = 0.5f;  // what an exact dark pixel may hold (CarveParams::dark_pixel_level)
  float keep_level = 0.0f;
  float sin2_carved = 0.0f;  // sin^2 of the elevation this frame can carve to
  // Inward normals of the bearing wedge's planes (CarvingGeometry; vertical: x and y only).
  Eigen::Vector2f left_normal = Eigen::Vector2f::Zero();
  Eigen::Vector2f right_normal = Eigen::Vector2f::Zero();
  // Robust carving: views that must vote to carve a voxel (CarveParams::carve_votes).
  int carve_votes = 1;
};

// Seabed-aware carving: a pixel may hold up to this many times the seabed's fitted prediction
// within this many range bins of it and still be the seabed's alone. The bins take the fit's
// error in range (a few millimetres of depth, a tenth of a degree of slope: under a bin at 10 m),
// the factor the spread of the prediction's scale over the frame (its median ratio).
constexpr int kSeabedSlackBins = 2;
constexpr double kSeabedHeadroom = 1.5;
// Behind a detector the fit is good to a few centimetres (the depth of the fitted plane under
// the middle and the edges of the footprint, against the true seabed: 2.4 to 2.9 cm on
// average over the manifold's noisy survey, where the noise-free fit is within 4 mm). Every
// view's error carves the seabed from above, so the voxels this far over the band are left
// to other views: neither carved nor kept (0, 3 and 6 cm: manifold 0.449, 0.569 and 0.568;
// seabed-objects 0.700, 0.777, 0.742).
constexpr double kSeabedDoubtBehindDetector_m = 0.03;

// Beam-aware: how far off the axis this frame can carve. A pixel carves a voxel where its bound
// I / p(theta) is at or below the keep level, so nowhere p(theta) is under the faintest
// bound a pixel gives on the axis over the keep level; past that the frame does nothing and
// its voxels are not visited. Behind a detector (dark pixels not exact) a frame carves inside
// +-aperture/2 only, at the paper's cost: a dark pixel there may hide a return up to the
// detection level, far above the keep level, so it bounds nothing off the axis, and a faint
// detected pixel, which holds more than a dark one, must not carve where a dark one cannot.
double carvedHalfElevation(const cv::Mat& pixels, const SonarModel& sonar, float keep_level,
                           bool dark_is_exact, float dark_level, double main_lobe_half) {
  const double aperture_half = 0.5 * sonar.verticalAperture();
  if (!dark_is_exact) {
    return aperture_half;
  }
  double faintest = dark_level;
  double min_lit = 0.0;
  cv::minMaxLoc(pixels, &min_lit, nullptr, nullptr, nullptr, pixels > 0.0f);
  if (min_lit > 0.0) {
    faintest = std::min(faintest, min_lit);
  }
  const double gain = faintest / static_cast<double>(keep_level);
  if (!(gain < 0.5)) {
    return aperture_half;
  }
  if (!(gain > 0.0)) {
    return main_lobe_half;
  }
  return std::clamp(SincSquaredBeam(sonar.verticalAperture()).halfAngleAt(10.0 * std::log10(gain)),
                    aperture_half, main_lobe_half);
}

// Four floats (ints) in one register where the target has them (GCC/Clang vector extension;
// plain code elsewhere). Comparisons give -1 (true) or 0 per lane.
using Float4 = float __attribute__((vector_size(16)));
using Int4 = std::int32_t __attribute__((vector_size(16)));
constexpr Float4 kLanes = {0.0f, 1.0f, 2.0f, 3.0f};
inline Float4 splat(float a) {
  return Float4{a, a, a, a};
}

// Metres by which a voxel may lie outside a plane of the bearing wedge and still be projected:
// far above fastAtan2's 1e-5 rad times any range, and the float error of its position.
constexpr float kWedgeSlack = 2e-3f;

// asin for the small angles of a vertical aperture: 1e-6 rad up to 15 degrees.
inline float smallAsin(float s) {
  const float s2 = s * s;
  return s * (1.0f + s2 * (1.0f / 6.0f + s2 * (3.0f / 40.0f + s2 * (5.0f / 112.0f))));
}

// What carving one block changed.
struct BlockChange {
  int observed = 0;     ///< voxels this view observed
  bool values = false;  ///< a voxel's value changed (the block's stamp moves)
  bool counts = false;  ///< a view or carve-vote count changed
};

// The counts of one block being carved: views, then carve votes (VoxelMap::counts); none
// (nullptr) in a map that keeps no counts, where one vote carves.
class BlockCounts {
 public:
  BlockCounts(std::uint8_t* counts, int carve_votes, BlockChange& change)
      : counts_(counts), carve_votes_(carve_votes), change_(change) {}
  // A view observed voxel i, above its sonar's axis (elevation > 0) or not.
  void viewed(int i, bool above) {
    if (counts_ == nullptr) {
      return;
    }
    std::uint8_t& v = counts_[i];
    const std::uint8_t side = above ? VoxelMap::kSeenAbove : VoxelMap::kSeenBelow;
    const std::uint8_t next = static_cast<std::uint8_t>(
        ((v & VoxelMap::kViewCountMask) < VoxelMap::kViewCountMask ? v + 1 : v) | side);
    if (next != v) {
      v = next;
      change_.counts = true;
    }
  }
  // One view's vote to carve voxel i; true once enough views agree.
  bool votedOut(int i) {
    if (counts_ == nullptr) {
      return true;
    }
    std::uint8_t& votes = counts_[VoxelMap::kBlockVoxels + i];
    bump(votes);
    return votes >= carve_votes_;
  }

 private:
  void bump(std::uint8_t& c) {
    if (c < 255) {
      ++c;
      change_.counts = true;
    }
  }
  std::uint8_t* counts_;
  int carve_votes_;
  BlockChange& change_;
};

// Carves the 512 voxels of one block in `values` and `counts` (nullptr: none kept).
BlockChange carveBlock(const CarvingGeometry& g, const FrameView& f,
                       const Eigen::Vector3f& first_centre_world, float voxel, float* values,
                       std::uint8_t* counts) {
  const Eigen::Vector3f p0 = f.R_sonar_world * first_centre_world + f.t_sonar_world;
  const Eigen::Vector3f dx = f.R_sonar_world.col(0) * voxel;
  const Eigen::Vector3f dy = f.R_sonar_world.col(1) * voxel;
  const Eigen::Vector3f dz = f.R_sonar_world.col(2) * voxel;
  const float rmin2 = g.rangeMinSq();
  const float rmax2 = g.rangeMaxSq();
  const float sin2 = g.sinHalfApertureSq();
  const float sin2_carved = f.sin2_carved;
  const float bin_min = g.binMin();
  const float inv_res = g.binInvResolution();
  BlockChange change;
  BlockCounts count(counts, f.carve_votes, change);
  // A view that finds voxel i lit at `level` (0: a vote to carve it).
  const auto observe = [&](int i, float level, bool above) {
    ++change.observed;
    count.viewed(i, above);
    if (level <= 0.0f) {
      if (count.votedOut(i)) {
        values[i] = 0.0f;
        change.values = true;
      }
    } else if (level < values[i]) {
      values[i] = level;
      change.values = true;
    }
  };
  for (int z = 0; z < kSide; ++z) {
    for (int y = 0; y < kSide; ++y) {
      const Eigen::Vector3f row_p0 = p0 + static_cast<float>(y) * dy + static_cast<float>(z) * dz;
      const int row_start = (z * kSide + y) * kSide;
      float* v = values + row_start;
      // First the row's eight voxels, four at a time: which are not carved yet (no view can
      // change a carved one) and lie inside the range window and the elevation this frame
      // carves to. Only those are projected.
      alignas(16) float xs[kSide], ys[kSide], zs[kSide], r2s[kSide];
      alignas(16) std::int32_t inside[kSide];
      for (int h = 0; h < kSide; h += 4) {
        const Float4 fx = kLanes + splat(static_cast<float>(h));
        const Float4 px = splat(row_p0.x()) + fx * splat(dx.x());
        const Float4 py = splat(row_p0.y()) + fx * splat(dx.y());
        const Float4 pz = splat(row_p0.z()) + fx * splat(dx.z());
        const Float4 r2 = px * px + py * py + pz * pz;
        Float4 value;
        std::memcpy(&value, v + h, sizeof value);
        // Inside the bearing wedge, but for a slack far above fastAtan2's error times any range
        // (the beam lookup decides at its edges).
        const Float4 left = px * splat(f.left_normal.x()) + py * splat(f.left_normal.y());
        const Float4 right = px * splat(f.right_normal.x()) + py * splat(f.right_normal.y());
        const Int4 in = (value != splat(0.0f)) & (r2 >= splat(rmin2)) & (r2 < splat(rmax2)) &
                        (pz * pz <= r2 * splat(sin2_carved)) & (left >= splat(-kWedgeSlack)) &
                        (right >= splat(-kWedgeSlack));
        std::memcpy(xs + h, &px, sizeof px);
        std::memcpy(ys + h, &py, sizeof py);
        std::memcpy(zs + h, &pz, sizeof pz);
        std::memcpy(r2s + h, &r2, sizeof r2);
        std::memcpy(inside + h, &in, sizeof in);
      }
      for (int x = 0; x < kSide; ++x) {
        if (inside[x] == 0) {
          continue;
        }
        const Eigen::Vector3f p(xs[x], ys[x], zs[x]);
        const float r2 = r2s[x];
        const float z2 = p.z() * p.z();
        const bool in_aperture = z2 <= r2 * sin2;
        if (!f.beam_aware && !in_aperture) {
          continue;
        }
        const int beam = g.beamOf(fastAtan2(p.y(), p.x()));
        if (beam < 0) {
          continue;
        }
        const float r = std::sqrt(r2);
        const int row = static_cast<int>((r - bin_min) * inv_res);
        if (row < 0 || row >= f.rows) {
          continue;
        }
        float intensity = f.pixels[row * f.cols + beam];
        bool on_seabed = false;
        if (f.first_return != nullptr) {
          const int bin =
              std::clamp(static_cast<int>((smallAsin(-p.z() / r) + f.limit_half_elevation) *
                                          f.inv_elevation_step),
                         0, f.elevation_bins - 1);
          const int ray = beam * f.elevation_bins + bin;
          if (r > f.first_return[ray] + f.margin) {
            continue;  // hidden behind the first surface: not observed by this frame
          }
          if (f.seabed_from != nullptr) {
            on_seabed = r >= f.seabed_from[ray];
            if (!on_seabed && r >= f.seabed_doubt_from[ray]) {
              continue;  // within the fit's doubt over the band
            }
            if (!on_seabed) {
              intensity = f.unexplained[row * f.cols + beam];
            } else if (!(intensity > 0.0f)) {
              continue;
            }
          }
        }
        if (f.beam_aware) {
          // What a return here would give on the beam's axis, at most: a lit pixel's
          // intensity, or what a dark one may hide, over the beam's gain at this elevation.
          float bound = 0.0f;
          if (intensity > 0.0f) {
            bound = intensity * g.inverseGain(std::abs(p.z()) / r);
          } else if (f.dark_is_exact) {
            bound = f.dark_level * g.inverseGain(std::abs(p.z()) / r);
            if (bound > f.keep_level) {
              continue;  // near the null, where a surface too returns less than a count
            }
          } else if (!in_aperture) {
            continue;  // below detection, where the beam is weaker than -3 dB: no bound
          }
          if (on_seabed) {
            // The fit says the seabed returns here, faint as it may be at grazing incidence.
            bound = std::max(bound, std::nextafter(f.keep_level, 1e30f));
          }
          if (bound <= f.keep_level) {
            bound = 0.0f;
          } else if (!in_aperture) {
            continue;  // outside +-aperture/2 a view carves; it does not keep
          }
          observe(row_start + x, bound, p.z() < 0.0f);
          continue;
        }
        observe(row_start + x, intensity, p.z() < 0.0f);
      }
    }
  }
  return change;
}

// Whether a block (its bounding sphere in the sonar frame) lies wholly behind the visibility
// limit of every ray it may cross, so that the frame observes none of its voxels. Rays are
// taken over the bearings and elevations the sphere spans, clamped to the limit's bins as
// the kernel clamps a voxel's.
bool hiddenBlock(const FrameView& f, const CarvingGeometry& g, const Eigen::Vector3d& c,
                 double radius) {
  if (f.first_return == nullptr) {
    return false;
  }
  const double range = c.norm();
  const double horizontal = std::hypot(c.x(), c.y());
  if (range <= radius || horizontal <= radius) {
    return false;
  }
  const double bearing = std::atan2(c.y(), c.x());
  const double half_bearing = std::asin(radius / horizontal);
  const int cols = f.cols;
  const auto beamAt = [&](double b, int outside) {
    const int beam = g.beamOf(static_cast<float>(b));
    return beam >= 0 ? beam : outside;
  };
  const int b0 = beamAt(bearing - half_bearing, 0);
  const int b1 = beamAt(bearing + half_bearing, cols - 1);
  const double elevation = std::asin(-c.z() / range);
  const double half_elevation = std::asin(radius / range);
  const auto binAt = [&](double e) {
    return std::clamp(static_cast<int>((e + f.limit_half_elevation) * f.inv_elevation_step), 0,
                      f.elevation_bins - 1);
  };
  const int k0 = binAt(elevation - half_elevation);
  const int k1 = binAt(elevation + half_elevation);
  const float nearest = static_cast<float>(range - radius) - f.margin;
  for (int b = std::min(b0, b1); b <= std::max(b0, b1); ++b) {
    const float* limits = f.first_return + static_cast<std::size_t>(b) * f.elevation_bins;
    for (int k = k0; k <= k1; ++k) {
      if (!(limits[k] < nearest)) {
        return false;
      }
    }
  }
  return true;
}

}  // namespace

FastCarver::FastCarver(VoxelMap& map, const SonarModel& sonar, const CarveParams& params,
                       ThreadPool& pool)
    : map_(map), params_(params), geometry_(sonar, params), pool_(pool) {
  if (params_.carve_votes < 1 || (params_.carve_votes > 1 && !map_.hasCounts())) {
    throw Error("carving", "carve_votes", "expected 1, or a map that keeps its voxels' counts");
  }
}

IntegrateStats FastCarver::integrate(const cv::Mat& image, const Eigen::Isometry3d& T_world_sonar,
                                     std::uint32_t stamp, const VisibilityLimit& visibility,
                                     const BeforeDetection* before) {
  const SonarModel& sonar = geometry_.sonar();
  if (image.type() != CV_32F || image.rows != sonar.rows() || image.cols != sonar.cols()) {
    throw Error("carving", "frame", "image does not match the sonar model");
  }
  cv::Mat pixels;
  cv::threshold(image, pixels, params_.intensity_threshold, 0.0, cv::THRESH_TOZERO);
  if (!pixels.isContinuous()) {
    pixels = pixels.clone();
  }
  const Eigen::Isometry3d T_sonar_world = T_world_sonar.inverse();
  FrameView frame{pixels.ptr<float>(0), pixels.cols, pixels.rows,
                  T_sonar_world.linear().cast<float>(), T_sonar_world.translation().cast<float>()};
  frame.beam_aware = carvesMainLobe(sonar, params_);
  frame.dark_is_exact = params_.dark_pixels == CarveParams::DarkPixels::Exact;
  frame.dark_level = static_cast<float>(params_.dark_pixel_level);
  frame.keep_level = static_cast<float>(effectiveKeepLevel(params_));
  frame.carve_votes = params_.carve_votes;
  frame.left_normal = geometry_.leftNormal().head<2>().cast<float>();
  frame.right_normal = geometry_.rightNormal().head<2>().cast<float>();
  const double half_elevation =
      frame.beam_aware ? carvedHalfElevation(pixels, sonar, frame.keep_level, frame.dark_is_exact,
                                             frame.dark_level, geometry_.carvedHalfElevation())
                       : geometry_.carvedHalfElevation();
  const double sin_half = std::sin(half_elevation);
  const double cos_half = std::cos(half_elevation);
  frame.sin2_carved = static_cast<float>(sin_half * sin_half);

  // Seabed-aware: the frame's seabed, what it explains of the pixels, and the rest.
  std::optional<SeabedPlane> seabed;
  cv::Mat unexplained;
  const bool behind_detector = behindDetector(before);
  if (params_.seabed_aware && frame.beam_aware) {
    seabed = seabed_.track(pixels, T_world_sonar, sonar, &pool_, before);
  }
  // The relief where it departs from the frame's plane by more than half a range bin (the
  // plane's own accuracy, noise-free): a flat seabed keeps its plane.
  const SeabedHeightfield* relief =
      seabed && params_.seabed_field &&
              reliefDeparture({T_world_sonar, *seabed}, *params_.seabed_field, sonar) >
                  0.5 * sonar.range().resolution_m
          ? params_.seabed_field.get()
          : nullptr;
  if (seabed) {
    unexplained = explainSeabed(
        pixels, predictSeabedImage(SeabedSurface{*seabed, relief}, T_world_sonar, sonar, &pool_),
        kSeabedSlackBins, kSeabedHeadroom);
  }

  // Blocks of the map inside the frustum's bounding box.
  Eigen::Vector3i lo, hi;
  if (!map_.blockSpan(geometry_.frustumBounds(T_world_sonar, half_elevation), lo, hi)) {
    return {};
  }
  map_.holdPages(lo, hi);  // before the threads (and the shadow limits) reach the blocks

  // What the frame sees: the visibility given, else, shadow-aware, its own shadow limits.
  VisibilityLimit own;
  ShadowLimits shadow;
  const VisibilityLimit* limit = visibility.first_return_m != nullptr ? &visibility : nullptr;
  if (limit == nullptr && params_.shadow_aware) {
    const ShadowLimitSetup setup{half_elevation, params_.elevation_step_rad, frame.beam_aware,
                                 frame.keep_level, frame.dark_is_exact};
    shadow =
        shadowLimits(seabed ? unexplained : pixels, T_world_sonar, map_, geometry_, setup, pool_);
    own.first_return_m = &shadow.first_return_m;
    own.elevation_bins = shadow.elevation_bins;
    own.elevation_step_rad = shadow.elevation_step_rad;
    own.half_elevation_rad = half_elevation;
    // The voxel that holds the surface and the pixel's range bin stay observed (the margin of
    // occlusion-aware carving; half of it, the voxel alone, kept ghosts: orbit F 0.659
    // against 0.716).
    own.margin_m = surfaceMargin(map_.voxelSize(), sonar.range().resolution_m);
    limit = &own;
  }
  // Seabed-aware: the rays' seabed bands, the seabed's limit folded into the visibility.
  SeabedBands seabed_bands;
  std::vector<float> with_seabed_limits;
  VisibilityLimit with_seabed;
  if (seabed) {
    with_seabed = limit != nullptr ? *limit : VisibilityLimit{};
    if (limit == nullptr) {
      with_seabed.elevation_bins = visibilityBins(half_elevation, params_.elevation_step_rad);
      with_seabed.elevation_step_rad = 2.0 * half_elevation / with_seabed.elevation_bins;
      with_seabed.half_elevation_rad = half_elevation;
      with_seabed.margin_m = surfaceMargin(map_.voxelSize(), sonar.range().resolution_m);
    }
    const double limit_half = with_seabed.half_elevation_rad > 0.0 ? with_seabed.half_elevation_rad
                                                                   : 0.5 * sonar.verticalAperture();
    seabed_bands =
        seabedBands(SeabedSurface{*seabed, relief}, T_world_sonar, sonar,
                    with_seabed.elevation_bins, limit_half, with_seabed.elevation_step_rad,
                    map_.voxelSize(), behind_detector ? kSeabedDoubtBehindDetector_m : 0.0);
    with_seabed_limits =
        limit != nullptr
            ? *limit->first_return_m
            : std::vector<float>(seabed_bands.to.size(), std::numeric_limits<float>::infinity());
    // What lies under the seabed is hidden from the frame.
    for (std::size_t i = 0; i < with_seabed_limits.size(); ++i) {
      with_seabed_limits[i] = std::min(
          with_seabed_limits[i], seabed_bands.to[i] - static_cast<float>(with_seabed.margin_m));
    }
    with_seabed.first_return_m = &with_seabed_limits;
    limit = &with_seabed;
  }
  if (limit != nullptr) {
    frame.first_return = limit->first_return_m->data();
    frame.elevation_bins = limit->elevation_bins;
    frame.limit_half_elevation =
        static_cast<float>(limit->half_elevation_rad > 0.0 ? limit->half_elevation_rad
                                                           : 0.5 * sonar.verticalAperture());
    frame.inv_elevation_step = static_cast<float>(1.0 / limit->elevation_step_rad);
    frame.margin = static_cast<float>(limit->margin_m);
    if (seabed) {
      frame.unexplained = unexplained.ptr<float>(0);
      frame.seabed_from = seabed_bands.from.data();
      frame.seabed_doubt_from = seabed_bands.doubt_from.data();
    }
  }
  const double block = map_.blockSize();
  const Eigen::Vector3i span = hi - lo + Eigen::Vector3i::Ones();
  const auto lines = static_cast<std::size_t>(span.y()) * static_cast<std::size_t>(span.z());
  const double voxel = map_.voxelSize();
  const double radius = 0.5 * std::sqrt(3.0) * block;

  std::atomic<std::size_t> visited{0}, changed_blocks{0}, observed{0};
  pool_.parallelFor(lines, 4, [&](std::size_t begin, std::size_t end) {
    alignas(64) float scratch[VoxelMap::kBlockVoxels];
    alignas(64) std::uint8_t scratch_counts[VoxelMap::kCountBytes];
    std::size_t my_visited = 0, my_changed = 0, my_observed = 0;
    for (std::size_t line = begin; line < end; ++line) {
      const int by = lo.y() + static_cast<int>(line % static_cast<std::size_t>(span.y()));
      const int bz = lo.z() + static_cast<int>(line / static_cast<std::size_t>(span.y()));
      for (int bx = lo.x(); bx <= hi.x(); ++bx) {
        const Eigen::Vector3i rel(bx, by, bz);
        const std::size_t b = map_.blockIndex(rel);
        const VoxelMap::BlockState state = map_.state(b);
        if (state == VoxelMap::BlockState::Free) {
          continue;
        }
        const Eigen::Vector3d origin = (rel + map_.firstBlock()).cast<double>() * block;
        const Eigen::Vector3d centre = origin + Eigen::Vector3d::Constant(0.5 * block);
        const Eigen::Vector3d centre_sonar = T_sonar_world * centre;
        if (!geometry_.sphereMayTouchFrustum(centre_sonar, radius, sin_half, cos_half) ||
            hiddenBlock(frame, geometry_, centre_sonar, radius)) {
          continue;
        }
        ++my_visited;
        map_.markVisited(b, stamp);
        float* values = map_.values(b);
        std::uint8_t* counts = map_.counts(b);
        if (values == nullptr) {  // unknown, or carved and unknown voxels only
          map_.copyValues(b, scratch);
          values = scratch;
        }
        if (counts == nullptr && map_.hasCounts()) {
          std::fill(std::begin(scratch_counts), std::end(scratch_counts), std::uint8_t{0});
          counts = scratch_counts;  // a new block: its counts start at 0
        }
        const Eigen::Vector3f first =
            (origin + Eigen::Vector3d::Constant(0.5 * voxel)).cast<float>();
        const BlockChange change =
            carveBlock(geometry_, frame, first, static_cast<float>(voxel), values, counts);
        my_observed += static_cast<std::size_t>(change.observed);
        if (change.values) {
          ++my_changed;
          map_.storeBlock(b, values, stamp, counts, false);
        } else if (change.counts && values == scratch) {
          // Votes on voxels not yet carved nor lit: kept for the views to come.
          map_.storeBlock(b, values, map_.stamp(b), counts, false);
        }
      }
    }
    visited += my_visited;
    changed_blocks += my_changed;
    observed += my_observed;
  });
  // Blocks the views have left for kColdFrames frames are masked if they can be: the views
  // move on (0.8 s at 10 Hz), and a block they come back to is expanded again when reached.
  constexpr std::uint32_t kColdFrames = 8;
  if (stamp % kColdFrames == 0) {
    map_.compactColdBlocks(stamp, kColdFrames);
  }
  return {visited.load(), changed_blocks.load(), observed.load()};
}

}  // namespace sonarcarve
