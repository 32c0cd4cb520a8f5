// The eviction schedule (pipeline/eviction_schedule.h): no cell's blocks are released while a
// frame still to be carved touches it or a neighbour's shell still reads its voxels, and no
// cell's candidates are freed while a frame still to be resolved touches it; and a long survey
// does let its early cells go long before it ends.
#include <gtest/gtest.h>

#include "pipeline/eviction_schedule.h"

namespace sonarcarve {
namespace {

// A lawnmower over a grid of cells: `lines` lines along x, each `line_frames` frames long,
// `spacing` cells apart in y; each frame touches a window of `reach` cells around it in x and
// y and the lowest `depth` cells in z.
std::vector<CellSpan> lawnmower(int lines, int line_frames, int spacing, int reach, int depth) {
  std::vector<CellSpan> spans;
  for (int line = 0; line < lines; ++line) {
    for (int i = 0; i < line_frames; ++i) {
      const int x = line % 2 == 0 ? i : line_frames - 1 - i;
      const int y = line * spacing;
      spans.push_back({Eigen::Vector3i(x - reach, y - reach, 0),
                       Eigen::Vector3i(x + reach, y + reach, depth - 1)});
    }
  }
  return spans;
}

const Eigen::Vector3i kGrid(40, 30, 4);

TEST(EvictionSchedule, NoCellIsFreedWhileAFrameToCarveOrResolveTouchesIt) {
  const EvictionSchedule s(lawnmower(5, 40, 6, 3, 2), kGrid);
  for (std::size_t f = 0; f < s.frames(); ++f) {
    const CellSpan& span = s.span(f);
    ASSERT_FALSE(span.empty());
    EXPECT_GE(s.ready(f), static_cast<std::int32_t>(f));
    for (int z = span.lo.z(); z <= span.hi.z(); ++z) {
      for (int y = span.lo.y(); y <= span.hi.y(); ++y) {
        for (int x = span.lo.x(); x <= span.hi.x(); ++x) {
          const std::size_t c = s.cellIndex({x, y, z});
          // Carved by every frame touching it before it is final...
          EXPECT_GE(s.last(c), static_cast<std::int32_t>(f));
          // ...final (with its neighbours) before a frame touching it resolves...
          EXPECT_LE(s.settled(c), s.ready(f));
          // ...its blocks kept until every frame touching it is carved...
          EXPECT_GE(s.released(c), static_cast<std::int32_t>(f));
          EXPECT_GE(s.released(c), s.settled(c));
          // ...and its candidates until every frame touching it is resolved.
          EXPECT_GE(s.freed(c), s.ready(f));
          EXPECT_GE(s.freed(c), s.released(c));
        }
      }
    }
  }
}

TEST(EvictionSchedule, ACellOutlivesTheNeighboursThatReadItsVoxels) {
  const EvictionSchedule s(lawnmower(4, 30, 5, 2, 2), kGrid);
  for (std::size_t c = 0; c < static_cast<std::size_t>(kGrid.prod()); ++c) {
    if (s.last(c) == EvictionSchedule::kNever) {
      EXPECT_EQ(s.freed(c), EvictionSchedule::kNever);
      continue;
    }
    EXPECT_GE(s.settled(c), s.last(c));
    const Eigen::Vector3i cell = s.cellCoords(c);
    for (int axis = 0; axis < 3; ++axis) {
      for (int step : {-1, 1}) {
        Eigen::Vector3i n = cell;
        n[axis] += step;
        if (n[axis] < 0 || n[axis] >= kGrid[axis]) {
          continue;
        }
        const std::size_t nc = s.cellIndex(n);
        EXPECT_GE(s.settled(c), s.last(nc));  // c's shell reads n's final voxels
        if (s.last(nc) != EvictionSchedule::kNever) {
          EXPECT_GE(s.released(nc), s.settled(c));  // n's blocks are still there when it does
        }
      }
    }
  }
}

TEST(EvictionSchedule, EveryEventHappensOnceAtItsStep) {
  const EvictionSchedule s(lawnmower(3, 25, 6, 2, 1), kGrid);
  std::vector<int> settled(static_cast<std::size_t>(kGrid.prod()), 0);
  std::vector<int> freed(settled.size(), 0);
  std::vector<int> released(settled.size(), 0);
  std::vector<int> ready(s.frames(), 0);
  for (std::size_t step = 0; step < s.frames(); ++step) {
    for (std::uint32_t c : s.cellsSettledAt(step)) {
      EXPECT_EQ(s.settled(c), static_cast<std::int32_t>(step));
      ++settled[c];
    }
    for (std::uint32_t f : s.framesReadyAt(step)) {
      EXPECT_EQ(s.ready(f), static_cast<std::int32_t>(step));
      ++ready[f];
    }
    for (std::uint32_t c : s.cellsReleasedAt(step)) {
      EXPECT_EQ(s.released(c), static_cast<std::int32_t>(step));
      ++released[c];
    }
    for (std::uint32_t c : s.cellsFreedAt(step)) {
      EXPECT_EQ(s.freed(c), static_cast<std::int32_t>(step));
      ++freed[c];
    }
  }
  for (std::size_t c = 0; c < settled.size(); ++c) {
    const int expected = s.last(c) == EvictionSchedule::kNever ? 0 : 1;
    EXPECT_EQ(settled[c], expected);
    EXPECT_EQ(freed[c], expected);
    EXPECT_EQ(released[c], expected);
  }
  for (int r : ready) {
    EXPECT_EQ(r, 1);
  }
}

TEST(EvictionSchedule, ALongSurveyLetsItsFirstLineGoWhileItFliesTheThird) {
  // Lines 6 cells apart with a reach of 3: line 0 is out of reach once line 2 starts.
  const EvictionSchedule s(lawnmower(5, 40, 6, 3, 2), kGrid);
  const std::size_t first_line_cell = s.cellIndex({10, 0, 0});
  ASSERT_NE(s.freed(first_line_cell), EvictionSchedule::kNever);
  EXPECT_LT(s.freed(first_line_cell), 3 * 40);
  // Its blocks go as soon as the line has passed it and its neighbours.
  EXPECT_LT(s.released(first_line_cell), 40);
}

TEST(EvictionSchedule, ACellIsSetAsideOverEachGapBetweenItsFramesAndBackBeforeTheNext) {
  // Lines 4 cells apart with a reach of 3: a cell is touched by two lines, with a gap between.
  const std::int32_t gap = 10;
  const EvictionSchedule s(lawnmower(5, 40, 4, 3, 2), kGrid, gap);
  const auto n_cells = static_cast<std::size_t>(kGrid.prod());
  // The frames touching each cell, by brute force.
  std::vector<std::vector<std::int32_t>> touches(n_cells);
  for (std::size_t f = 0; f < s.frames(); ++f) {
    for (std::size_t c = 0; c < n_cells; ++c) {
      if (s.span(f).contains(s.cellCoords(c))) {
        touches[c].push_back(static_cast<std::int32_t>(f));
      }
    }
  }
  std::vector<std::vector<std::int32_t>> aside(n_cells), back(n_cells);
  for (std::size_t step = 0; step < s.frames(); ++step) {
    for (std::uint32_t c : s.cellsAsideAt(step)) {
      aside[c].push_back(static_cast<std::int32_t>(step));
    }
    for (std::uint32_t c : s.cellsBackBefore(step)) {
      back[c].push_back(static_cast<std::int32_t>(step));
    }
  }
  std::size_t gaps = 0;
  for (std::size_t c = 0; c < n_cells; ++c) {
    std::vector<std::int32_t> expected_aside, expected_back;
    for (std::size_t i = 1; i < touches[c].size(); ++i) {
      if (touches[c][i] - touches[c][i - 1] > gap) {
        expected_aside.push_back(touches[c][i - 1]);
        expected_back.push_back(touches[c][i]);
      }
    }
    EXPECT_EQ(aside[c], expected_aside) << "cell " << c;
    EXPECT_EQ(back[c], expected_back) << "cell " << c;
    gaps += expected_aside.size();
    // Nothing reads a cell while it is aside: it and its neighbours settle, and it is
    // released, only after its last frame.
    for (std::int32_t t : expected_back) {
      EXPECT_GE(s.settled(c), t);
      EXPECT_GE(s.released(c), t);
    }
  }
  EXPECT_GT(gaps, 100u);  // the survey does come back over cells it left
  // Without a gap, nothing is set aside.
  const EvictionSchedule none(lawnmower(5, 40, 4, 3, 2), kGrid);
  for (std::size_t step = 0; step < none.frames(); ++step) {
    EXPECT_TRUE(none.cellsAsideAt(step).empty());
    EXPECT_TRUE(none.cellsBackBefore(step).empty());
  }
}

TEST(EvictionSchedule, SpansOutsideTheGridAreClippedAndEmptyFramesAreReadyAtOnce) {
  std::vector<CellSpan> spans{{Eigen::Vector3i(-5, -5, -5), Eigen::Vector3i(1, 1, 1)},
                              CellSpan{},
                              {Eigen::Vector3i(100, 100, 100), Eigen::Vector3i(120, 120, 120)}};
  const EvictionSchedule s(spans, Eigen::Vector3i(4, 4, 4));
  EXPECT_EQ(s.span(0).lo, Eigen::Vector3i::Zero());
  EXPECT_EQ(s.ready(1), 1);
  EXPECT_EQ(s.ready(2), 2);
  EXPECT_EQ(s.last(s.cellIndex({1, 1, 1})), 0);
  EXPECT_EQ(s.last(s.cellIndex({3, 3, 3})), EvictionSchedule::kNever);
}

}  // namespace
}  // namespace sonarcarve
