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
  cell_ = std::max({reach, std::sqrt(size.x() * size.y() / kMaxCells), 1e-6});
  origin_ = lo;
  columns_ = static_cast<int>(std::ceil(size.x() / cell_)) + 1;
  rows_ = static_cast<int>(std::ceil(size.y() / cell_)) + 1;
  // Bucketed per cell first, then laid out flat: each cell's indices together, in ascending order.
  std::vector<std::vector<int>> cells(static_cast<size_t>(columns_) * rows_);
  for (size_t i = 0; i < rects.size(); ++i) {
    const Vec2 a = (rects[i].min - margin - origin_) / cell_, b = (rects[i].max + margin - origin_) / cell_;
    const int c0 = std::clamp(static_cast<int>(std::floor(a.x())), 0, columns_ - 1);
    const int c1 = std::clamp(static_cast<int>(std::floor(b.x())), 0, columns_ - 1);
    const int r0 = std::clamp(static_cast<int>(std::floor(a.y())), 0, rows_ - 1);
    const int r1 = std::clamp(static_cast<int>(std::floor(b.y())), 0, rows_ - 1);
    for (int row = r0; row <= r1; ++row) {
      for (int column = c0; column <= c1; ++column) {
        cells[static_cast<size_t>(row) * columns_ + column].push_back(static_cast<int>(i));
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
  const Vec2 at = (p - origin_) / cell_;
  // Also catches NaN: a body that physics has thrown off still gets every rectangle.
  if (!(at.x() >= 0.0 && at.y() >= 0.0 && at.x() < columns_ && at.y() < rows_)) return all_;
  const size_t cell = static_cast<size_t>(static_cast<int>(at.y())) * columns_ + static_cast<int>(at.x());
  return std::span<const int>(items_).subspan(first_[cell], first_[cell + 1] - first_[cell]);
}

}  // namespace physltl::geometry
