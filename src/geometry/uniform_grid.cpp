#include "physltl/geometry/uniform_grid.h"

#include <algorithm>
#include <cmath>

namespace physltl::geometry {

UniformGrid::UniformGrid(const Vec2& origin, double cell, int columns, int rows)
    : origin_(origin), cell_(cell), columns_(std::max(1, columns)), rows_(std::max(1, rows)) {}

UniformGrid UniformGrid::covering(const Rect& bounds, double cell) {
  return {bounds.min, cell, static_cast<int>(std::ceil(bounds.size().x() / cell)), static_cast<int>(std::ceil(bounds.size().y() / cell))};
}

long long UniformGrid::neighbour(std::size_t index, int dx, int dy) const {
  const int column = column_of(index) + dx, row = row_of(index) + dy;
  return contains(column, row) ? static_cast<long long>(this->index(column, row)) : -1;
}

int UniformGrid::clamped(double at, int count) {
  const double floor = std::floor(at);
  return floor >= 0 ? static_cast<int>(std::min(floor, static_cast<double>(count - 1))) : 0;
}

}  // namespace physltl::geometry
