// MinIntensityOcTree: an OctoMap octree whose leaves hold a voxel's minimum intensity (float).
// Built on OctoMap's OcTreeBaseImpl with OcTreeDataNode<float>, so OctoMap's own key
// arithmetic, iterators and pruning (children with equal values collapse) apply.
// Internal to core: OctoMap types stay out of public headers except here.
#pragma once

#include <octomap/AbstractOcTree.h>
#include <octomap/OcTreeBaseImpl.h>
#include <octomap/OcTreeDataNode.h>

namespace sonarcarve {

using MinIntensityNode = octomap::OcTreeDataNode<float>;

class MinIntensityOcTree
    : public octomap::OcTreeBaseImpl<MinIntensityNode, octomap::AbstractOcTree> {
 public:
  explicit MinIntensityOcTree(double resolution_m)
      : octomap::OcTreeBaseImpl<MinIntensityNode, octomap::AbstractOcTree>(resolution_m) {}
  MinIntensityOcTree* create() const override { return new MinIntensityOcTree(resolution); }
  std::string getTreeType() const override { return "MinIntensityOcTree"; }

  /// value(key) = min(value(key), intensity), creating the leaf (or expanding a pruned one).
  void updateMin(const octomap::OcTreeKey& key, float intensity);
};

}  // namespace sonarcarve
