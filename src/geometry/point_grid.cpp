#include "physltl/geometry/point_grid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace physltl::geometry {
namespace {

// A grid this fine over the area is plenty: beyond it the buckets only cost memory.
constexpr int kMaxCellsPerSide = 1024;

}  // namespace

PointGrid::PointGrid(const Rect& area, double cell, std::span<const Vec2> points) {
  if (!(cell > 0) || !area.min.allFinite() || !area.max.allFinite()) {
    throw std::invalid_argument("PointGrid: a positive cell and a finite area");
  }
  const Vec2 size = (area.max - area.min).cwiseMax(Vec2::Zero());
  const double side = std::max(cell, size.maxCoeff() / kMaxCellsPerSide);
  grid_ = UniformGrid(area.min, side, static_cast<int>(std::ceil(size.x() / side)), static_cast<int>(std::ceil(size.y() / side)));
  cells_.resize(grid_.size());
  points_.assign(points.begin(), points.end());
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const int c = cell_of(points_[i]);
    cell_of_point_.push_back(c);
    cells_[static_cast<std::size_t>(c)].push_back(static_cast<int>(i));
  }
}

void PointGrid::move(int i, const Vec2& p) {
  const auto index = static_cast<std::size_t>(i);
  points_[index] = p;
  const int now = cell_of(p);
  int& was = cell_of_point_[index];
  if (now == was) return;
  std::vector<int>& old_cell = cells_[static_cast<std::size_t>(was)];
  old_cell.erase(std::find(old_cell.begin(), old_cell.end(), i));
  cells_[static_cast<std::size_t>(now)].push_back(i);
  was = now;
}

void PointGrid::near(const Vec2& centre, double radius, std::vector<int>& out) const {
  out.clear();
  const int c0 = grid_.column(centre.x() - radius), c1 = grid_.column(centre.x() + radius);
  const int r0 = grid_.row(centre.y() - radius), r1 = grid_.row(centre.y() + radius);
  for (int r = r0; r <= r1; ++r) {
    for (int c = c0; c <= c1; ++c) {
      for (int i : cells_[grid_.index(c, r)]) {
        const Vec2 d = (points_[static_cast<std::size_t>(i)] - centre).cwiseAbs();
        if (d.x() <= radius && d.y() <= radius) out.push_back(i);
      }
    }
  }
}

}  // namespace physltl::geometry
