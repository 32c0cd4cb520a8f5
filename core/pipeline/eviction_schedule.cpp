#include "pipeline/eviction_schedule.h"

#include <algorithm>

namespace sonarcarve {

template <typename F>
void EvictionSchedule::forEachCell(const CellSpan& span, F&& f) const {
  for (int z = span.lo.z(); z <= span.hi.z(); ++z) {
    for (int y = span.lo.y(); y <= span.hi.y(); ++y) {
      for (int x = span.lo.x(); x <= span.hi.x(); ++x) {
        f(cellIndex({x, y, z}));
      }
    }
  }
}

template <typename F>
void EvictionSchedule::forEachFaceNeighbour(std::size_t cell, F&& f) const {
  const Eigen::Vector3i c = cellCoords(cell);
  for (int axis = 0; axis < 3; ++axis) {
    for (int step : {-1, 1}) {
      Eigen::Vector3i n = c;
      n[axis] += step;
      if (n[axis] >= 0 && n[axis] < cells_[axis]) {
        f(cellIndex(n));
      }
    }
  }
}

Eigen::Vector3i EvictionSchedule::cellCoords(std::size_t cell) const {
  const auto nx = static_cast<std::size_t>(cells_.x());
  const auto ny = static_cast<std::size_t>(cells_.y());
  return Eigen::Vector3i(static_cast<int>(cell % nx), static_cast<int>((cell / nx) % ny),
                         static_cast<int>(cell / (nx * ny)));
}

std::vector<std::int32_t> EvictionSchedule::latestAround(
    const std::vector<std::int32_t>& at) const {
  std::vector<std::int32_t> latest(at.size(), kNever);
  for (std::size_t c = 0; c < at.size(); ++c) {
    if (last_[c] == kNever) {
      continue;
    }
    std::int32_t l = at[c];
    forEachFaceNeighbour(c, [&](std::size_t n) { l = std::max(l, at[n]); });
    latest[c] = l;
  }
  return latest;
}

EvictionSchedule::EvictionSchedule(const std::vector<CellSpan>& spans, const Eigen::Vector3i& cells,
                                   std::int32_t aside_gap)
    : spans_(spans), cells_(cells) {
  const auto n_cells = static_cast<std::size_t>(cells.x()) * cells.y() * cells.z();
  first_.assign(n_cells, kNever);
  last_.assign(n_cells, kNever);
  aside_at_.resize(spans_.size());
  back_before_.resize(spans_.size());
  for (std::size_t f = 0; f < spans_.size(); ++f) {
    CellSpan& s = spans_[f];
    s.lo = s.lo.cwiseMax(Eigen::Vector3i::Zero());
    s.hi = s.hi.cwiseMin(cells - Eigen::Vector3i::Ones());
    if (s.empty()) {
      continue;
    }
    const auto frame = static_cast<std::int32_t>(f);
    forEachCell(s, [&](std::size_t c) {
      if (first_[c] == kNever) {
        first_[c] = frame;
      } else if (aside_gap > 0 && frame - last_[c] > aside_gap) {
        aside_at_[static_cast<std::size_t>(last_[c])].push_back(static_cast<std::uint32_t>(c));
        back_before_[f].push_back(static_cast<std::uint32_t>(c));
      }
      last_[c] = frame;
    });
  }
  settled_ = latestAround(last_);
  ready_.assign(spans_.size(), kNever);
  freed_.assign(n_cells, kNever);
  for (std::size_t f = 0; f < spans_.size(); ++f) {
    if (spans_[f].empty()) {
      ready_[f] = static_cast<std::int32_t>(f);
      continue;
    }
    std::int32_t r = static_cast<std::int32_t>(f);
    forEachCell(spans_[f], [&](std::size_t c) { r = std::max(r, settled_[c]); });
    ready_[f] = r;
    forEachCell(spans_[f], [&](std::size_t c) { freed_[c] = std::max(freed_[c], r); });
  }
  released_ = latestAround(settled_);
  for (std::size_t c = 0; c < n_cells; ++c) {
    freed_[c] = std::max(freed_[c], released_[c]);
  }
  settled_at_.resize(spans_.size());
  ready_at_.resize(spans_.size());
  released_at_.resize(spans_.size());
  freed_at_.resize(spans_.size());
  for (std::size_t c = 0; c < n_cells; ++c) {
    if (last_[c] != kNever) {
      const auto cell = static_cast<std::uint32_t>(c);
      settled_at_[static_cast<std::size_t>(settled_[c])].push_back(cell);
      released_at_[static_cast<std::size_t>(released_[c])].push_back(cell);
      freed_at_[static_cast<std::size_t>(freed_[c])].push_back(cell);
    }
  }
  for (std::size_t f = 0; f < spans_.size(); ++f) {
    ready_at_[static_cast<std::size_t>(ready_[f])].push_back(static_cast<std::uint32_t>(f));
  }
}

}  // namespace sonarcarve
