#pragma once
// Fixed rectangles bucketed on a uniform grid, so that "which of them may come within `reach` of this
// point" is one lookup instead of a scan. The physics step and INFERENCE ask it for every moving body at
// every step, and a World with many rooms has a hundred walls or more.

#include "physltl/geometry/shapes.h"
#include "physltl/geometry/uniform_grid.h"

#include <span>
#include <vector>

namespace physltl::geometry {

class RectGrid {
 public:
  RectGrid() = default;  // holds no rectangles
  RectGrid(std::span<const Rect> rects, double reach);

  // Indices, ascending, of every rectangle that has a point within `reach` of `p` in x and in y, and
  // perhaps of a few more: callers still test the ones they get.
  std::span<const int> near(const Vec2& p) const;

 private:
  UniformGrid grid_;
  std::vector<int> first_;  // per cell, where its indices start in items_; one more entry at the end
  std::vector<int> items_;
  std::vector<int> all_;    // for points off the grid
};

}  // namespace physltl::geometry
