#pragma once
// Points that move, bucketed on a uniform grid: which of them lie near a place costs what the points near
// it cost, not a scan of all of them. The physics step asks it which boxes a moving body may touch, and
// INFERENCE which boxes stand near a contact segment; moving a point moves it between buckets.

#include "physltl/geometry/shapes.h"
#include "physltl/geometry/uniform_grid.h"

#include <span>
#include <vector>

namespace physltl::geometry {

class PointGrid {
 public:
  PointGrid() = default;  // no points
  // `area`: where the points mostly are (points outside it land in the border cells); `cell`: the side of
  // a bucket, about the radius of the usual query.
  PointGrid(const Rect& area, double cell, std::span<const Vec2> points);

  std::size_t size() const { return points_.size(); }
  const Vec2& position(int i) const { return points_[static_cast<std::size_t>(i)]; }
  void move(int i, const Vec2& p);

  // Replaces `out` with the indices of every point within `radius` of `centre` in x and in y, in no
  // particular order (sort them where the order matters).
  void near(const Vec2& centre, double radius, std::vector<int>& out) const;

 private:
  int cell_of(const Vec2& p) const { return static_cast<int>(grid_.index_of(p)); }

  UniformGrid grid_;
  std::vector<std::vector<int>> cells_;
  std::vector<int> cell_of_point_;
  std::vector<Vec2> points_;
};

}  // namespace physltl::geometry
