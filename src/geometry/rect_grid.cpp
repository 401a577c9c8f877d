#include "physltl/geometry/rect_grid.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace physltl::geometry {
namespace {

// Enough cells that a query sees few rectangles, few enough that a large sparse World stays small.
constexpr double kMaxCells = 1 << 16;

}  // namespace

RectGrid::RectGrid(std::span<const Rect> rects, double reach) : all_(rects.size()) {
  std::iota(all_.begin(), all_.end(), 0);
  if (rects.empty()) return;
  const Vec2 margin = Vec2::Constant(reach);
  Vec2 lo = rects[0].min - margin, hi = rects[0].max + margin;
  for (const Rect& r : rects) lo = lo.cwiseMin(r.min - margin), hi = hi.cwiseMax(r.max + margin);
  const Vec2 size = hi - lo;
  const double cell = std::max({reach, std::sqrt(size.x() * size.y() / kMaxCells), 1e-6});
  grid_ = UniformGrid(lo, cell, static_cast<int>(std::ceil(size.x() / cell)) + 1, static_cast<int>(std::ceil(size.y() / cell)) + 1);
  // Bucketed per cell first, then laid out flat: each cell's indices together, in ascending order.
  std::vector<std::vector<int>> cells(grid_.size());
  for (size_t i = 0; i < rects.size(); ++i) {
    const Vec2 a = rects[i].min - margin, b = rects[i].max + margin;
    for (int row = grid_.row(a.y()); row <= grid_.row(b.y()); ++row) {
      for (int column = grid_.column(a.x()); column <= grid_.column(b.x()); ++column) {
        cells[grid_.index(column, row)].push_back(static_cast<int>(i));
      }
    }
  }
  first_.reserve(cells.size() + 1);
  for (const auto& cell : cells) {
    first_.push_back(static_cast<int>(items_.size()));
    items_.insert(items_.end(), cell.begin(), cell.end());
  }
  first_.push_back(static_cast<int>(items_.size()));
}

std::span<const int> RectGrid::near(const Vec2& p) const {
  if (first_.empty()) return all_;
  const Vec2 at = (p - grid_.origin()) / grid_.cell();
  // Off the grid gets every rectangle, NaN too: a body that physics has thrown off still meets them all.
  if (!(at.x() >= 0.0 && at.y() >= 0.0 && at.x() < grid_.columns() && at.y() < grid_.rows())) return all_;
  const size_t cell = grid_.index(static_cast<int>(at.x()), static_cast<int>(at.y()));
  return std::span<const int>(items_).subspan(first_[cell], first_[cell + 1] - first_[cell]);
}

}  // namespace physltl::geometry
