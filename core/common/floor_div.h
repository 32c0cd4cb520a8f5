// Integer division rounded towards minus infinity (C++'s `/` rounds towards zero): the block,
// tile or cell of a voxel index that may be negative.
#pragma once

namespace sonarcarve {

template <typename Int>
constexpr Int floorDiv(Int a, Int b) {
  return a >= 0 ? a / b : -((-a + b - 1) / b);
}

}  // namespace sonarcarve
