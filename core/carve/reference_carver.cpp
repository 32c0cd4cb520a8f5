#include "carve/reference_carver.h"

#include <cmath>
#include <limits>

#include "carve/internal/min_intensity_octree.h"
#include "common/error.h"

namespace sonarcarve {

void MinIntensityOcTree::updateMin(const octomap::OcTreeKey& key, float intensity) {
  constexpr float kUnknown = std::numeric_limits<float>::infinity();
  bool fresh = false;  // the node was created by this walk: it has no value of its own yet
  if (root == nullptr) {
    root = new MinIntensityNode(kUnknown);
    tree_size++;
    fresh = true;
  }
  MinIntensityNode* node = root;
  for (int depth = 0; depth < static_cast<int>(tree_depth); ++depth) {
    const unsigned child = octomap::computeChildIdx(key, static_cast<int>(tree_depth) - 1 - depth);
    if (!nodeChildExists(node, child)) {
      if (!fresh && !nodeHasChildren(node)) {
        // An old leaf above the voxel level is a pruned node: its value holds for every child.
        expandNode(node);
      } else {
        createNodeChild(node, child)->setValue(kUnknown);
        fresh = true;
      }
    } else {
      fresh = false;
    }
    node = getNodeChild(node, child);
  }
  if (intensity < node->getValue()) {
    node->setValue(intensity);
  }
}

ReferenceCarver::ReferenceCarver(const SonarModel& sonar, const CarveParams& params)
    : sonar_(sonar),
      params_(params),
      tree_(std::make_unique<MinIntensityOcTree>(params.voxel_size_m)) {
  const double half = 0.5 * sonar.verticalAperture();
  const int steps = static_cast<int>(std::floor(2.0 * half / params.elevation_step_rad + 1e-9));
  for (int k = 0; k <= steps; ++k) {
    const double theta = -half + k * params.elevation_step_rad;
    arc_cos_.push_back(std::cos(theta));
    arc_sin_.push_back(std::sin(theta));
  }
}

ReferenceCarver::~ReferenceCarver() = default;

void ReferenceCarver::integrate(const cv::Mat& image, const Eigen::Isometry3d& T_world_sonar) {
  if (image.type() != CV_32F || image.rows != sonar_.rows() || image.cols != sonar_.cols()) {
    throw Error("carving", "frame", "image does not match the sonar model");
  }
  const double range_min = std::max(params_.range_min_m, sonar_.range().min_m);
  const double range_max =
      params_.range_max_m > 0.0 ? params_.range_max_m : sonar_.range().maxRange();
  const auto threshold = static_cast<float>(params_.intensity_threshold);
  const Eigen::Matrix3d R = T_world_sonar.linear();
  const Eigen::Vector3d t = T_world_sonar.translation();
  for (int col = 0; col < image.cols; ++col) {
    const double bearing = sonar_.bearings().centre(col);
    const double cb = std::cos(bearing), sb = std::sin(bearing);
    for (int row = 0; row < image.rows; ++row) {
      const double r = sonar_.range().centre(row);
      if (r < range_min || r >= range_max) {
        continue;
      }
      const float pixel = image.at<float>(row, col);
      const float intensity = pixel > threshold ? pixel : 0.0f;
      for (std::size_t k = 0; k < arc_cos_.size(); ++k) {
        const Eigen::Vector3d p_sonar(r * arc_cos_[k] * cb, r * arc_cos_[k] * sb, -r * arc_sin_[k]);
        const Eigen::Vector3d p = R * p_sonar + t;
        octomap::OcTreeKey key;
        if (!tree_->coordToKeyChecked(p.x(), p.y(), p.z(), key)) {
          continue;
        }
        // The map holds the voxels whose centres lie in the region.
        if (params_.region &&
            !params_.region->contains(Eigen::Vector3d(
                tree_->keyToCoord(key[0]), tree_->keyToCoord(key[1]), tree_->keyToCoord(key[2])))) {
          continue;
        }
        tree_->updateMin(key, intensity);
      }
    }
  }
  if (++frames_ % 10 == 0) {
    tree_->prune();
  }
}

std::vector<Eigen::Vector3i> ReferenceCarver::occupiedVoxels() const {
  std::vector<Eigen::Vector3i> voxels;
  const int max_depth = static_cast<int>(tree_->getTreeDepth());
  for (auto it = tree_->begin_leafs(), end = tree_->end_leafs(); it != end; ++it) {
    const float v = it->getValue();
    if (!(v > 0.0f) || std::isinf(v)) {
      continue;
    }
    // A pruned leaf stands for all the voxels below it.
    const int side = 1 << (max_depth - static_cast<int>(it.getDepth()));
    const octomap::OcTreeKey first = it.getIndexKey();
    for (int z = 0; z < side; ++z) {
      for (int y = 0; y < side; ++y) {
        for (int x = 0; x < side; ++x) {
          voxels.emplace_back(first[0] + x - 32768, first[1] + y - 32768, first[2] + z - 32768);
        }
      }
    }
  }
  return voxels;
}

float ReferenceCarver::value(const Eigen::Vector3i& voxel) const {
  const octomap::OcTreeKey key(static_cast<octomap::key_type>(voxel.x() + 32768),
                               static_cast<octomap::key_type>(voxel.y() + 32768),
                               static_cast<octomap::key_type>(voxel.z() + 32768));
  const MinIntensityNode* node = tree_->search(key);
  return node == nullptr ? std::numeric_limits<float>::infinity() : node->getValue();
}

std::size_t ReferenceCarver::nodeCount() const {
  return tree_->size();
}
std::size_t ReferenceCarver::memoryBytes() const {
  return tree_->memoryUsage();
}

}  // namespace sonarcarve
