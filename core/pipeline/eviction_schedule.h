// When each part of the map is final, in a post-processing run whose poses are all known before
// carving (docs/scaling.md, "Letting finished blocks go"). The map's block table is paged in
// cells of 8^3 blocks (VoxelMap pages); frame f "touches" the cells its frustum's bounding box
// meets. With frames carved in order 0, 1, ...:
//   last(c)     the last frame that touches cell c: c's voxels are final once it is carved;
//   settled(c)  max last() of c and its six face neighbours: c's surface candidates (occupied
//               voxels with a face neighbour not occupied) are final, and can be counted;
//   ready(f)    max settled() over the cells f touches: f's occlusion resolution can run;
//   released(c) max settled() of c and its neighbours: no frame carves c any more and no
//               neighbour's shell still reads c's voxels, so c's blocks can go (what
//               occlusion resolution needs of c, its candidates, has been taken at settled(c));
//   freed(c)    max of ready() over the frames touching c and released(c): every frame that
//               sees c is resolved, so c's surface points are final and its candidates go.
// Blocks go long before candidates where lines overlap: on a lawnmower whose swath (20 m at
// 10 m range) is four times its line spacing, a cell is carved by two or three lines but
// seen by frames whose own cells are carved by lines further on (docs/scaling.md).
// A cell the frames leave and come back to more than `gap` frames later (a lawnmower's next
// line) can be set aside meanwhile (carve/page_spill.h): after the frame before the gap
// (aside), to be held again before the frame after it (back). Neither a cell set aside nor its
// neighbours settle during the gap: settled() is at or after its last frame.
// Each step n (after frame n is carved) lists what becomes possible at n.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace sonarcarve {

/// The cells [lo, hi] (inclusive, page coordinates) a frame touches; empty when lo > hi.
struct CellSpan {
  Eigen::Vector3i lo = Eigen::Vector3i::Zero();
  Eigen::Vector3i hi = Eigen::Vector3i::Constant(-1);
  bool empty() const { return (lo.array() > hi.array()).any(); }
  bool contains(const Eigen::Vector3i& c) const {
    return (c.array() >= lo.array()).all() && (c.array() <= hi.array()).all();
  }
};

class EvictionSchedule {
 public:
  static constexpr std::int32_t kNever = -1;

  /// `spans` of frames 0..n-1 in carving order, over a grid of `cells` cells (index
  /// (z * cells.y() + y) * cells.x() + x, as VoxelMap::pageIndex). Cells no frame touches for
  /// more than `aside_gap` frames between two that do are set aside (0: none).
  EvictionSchedule(const std::vector<CellSpan>& spans, const Eigen::Vector3i& cells,
                   std::int32_t aside_gap = 0);

  std::size_t frames() const { return ready_.size(); }
  const CellSpan& span(std::size_t frame) const { return spans_[frame]; }
  std::int32_t first(std::size_t cell) const { return first_[cell]; }
  std::int32_t last(std::size_t cell) const { return last_[cell]; }
  std::int32_t settled(std::size_t cell) const { return settled_[cell]; }
  std::int32_t ready(std::size_t frame) const { return ready_[frame]; }
  std::int32_t released(std::size_t cell) const { return released_[cell]; }
  std::int32_t freed(std::size_t cell) const { return freed_[cell]; }
  /// What becomes possible after frame `step` is carved.
  const std::vector<std::uint32_t>& cellsSettledAt(std::size_t step) const {
    return settled_at_[step];
  }
  const std::vector<std::uint32_t>& framesReadyAt(std::size_t step) const {
    return ready_at_[step];
  }
  const std::vector<std::uint32_t>& cellsReleasedAt(std::size_t step) const {
    return released_at_[step];
  }
  const std::vector<std::uint32_t>& cellsFreedAt(std::size_t step) const { return freed_at_[step]; }
  /// Cells no frame touches for more than the gap after `step`, but one does later.
  const std::vector<std::uint32_t>& cellsAsideAt(std::size_t step) const { return aside_at_[step]; }
  /// Cells set aside that frame `frame` touches: to be held again before it is carved.
  const std::vector<std::uint32_t>& cellsBackBefore(std::size_t frame) const {
    return back_before_[frame];
  }
  Eigen::Vector3i cellCoords(std::size_t cell) const;
  std::size_t cellIndex(const Eigen::Vector3i& c) const {
    return (static_cast<std::size_t>(c.z()) * cells_.y() + c.y()) * cells_.x() + c.x();
  }

 private:
  template <typename F>
  void forEachCell(const CellSpan& span, F&& f) const;
  template <typename F>
  void forEachFaceNeighbour(std::size_t cell, F&& f) const;
  /// Per cell a frame touches, the latest of `at` over the cell and its face neighbours; kNever
  /// for cells no frame touches.
  std::vector<std::int32_t> latestAround(const std::vector<std::int32_t>& at) const;

  std::vector<CellSpan> spans_;
  Eigen::Vector3i cells_;
  std::vector<std::int32_t> first_, last_, settled_, ready_, released_, freed_;
  std::vector<std::vector<std::uint32_t>> settled_at_, ready_at_, released_at_, freed_at_;
  std::vector<std::vector<std::uint32_t>> aside_at_, back_before_;
};

}  // namespace sonarcarve
