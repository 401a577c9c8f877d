#pragma once
// The cell arithmetic of every grid of the program: a rectangle cut into square cells of one side, row by
// row from its min corner. The grids above it (where a disc's centre can go, bucketed points and
// rectangles, the free space's obstacles, the decomposition's triangles, the reachability of regions, the
// look-ahead's lattice) keep what their cells hold; this keeps where a cell is.

#include "physltl/geometry/shapes.h"

#include <cstddef>

namespace physltl::geometry {

class UniformGrid {
 public:
  UniformGrid() = default;  // one cell of side 1 at the origin
  // `columns` x `rows` cells (at least one each) of side `cell`, the first with its min corner at `origin`.
  UniformGrid(const Vec2& origin, double cell, int columns, int rows);
  // The cells of side `cell` that cover `bounds` from its min corner: as many as it takes, at least one a side.
  static UniformGrid covering(const Rect& bounds, double cell);

  const Vec2& origin() const { return origin_; }
  double cell() const { return cell_; }
  int columns() const { return columns_; }
  int rows() const { return rows_; }
  std::size_t size() const { return static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_); }

  std::size_t index(int column, int row) const {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(columns_) + static_cast<std::size_t>(column);
  }
  int column_of(std::size_t index) const { return static_cast<int>(index % static_cast<std::size_t>(columns_)); }
  int row_of(std::size_t index) const { return static_cast<int>(index / static_cast<std::size_t>(columns_)); }
  bool contains(int column, int row) const { return column >= 0 && row >= 0 && column < columns_ && row < rows_; }
  // The index of the cell `dx` columns and `dy` rows from cell `index`, or -1 past the grid's edge.
  long long neighbour(std::size_t index, int dx, int dy) const;

  // The column holding x and the row holding y, clamped into the grid (a NaN lands in the first).
  int column(double x) const { return clamped((x - origin_.x()) / cell_, columns_); }
  int row(double y) const { return clamped((y - origin_.y()) / cell_, rows_); }
  std::size_t index_of(const Vec2& p) const { return index(column(p.x()), row(p.y())); }
  Vec2 centre(int column, int row) const { return origin_ + cell_ * Vec2(column + 0.5, row + 0.5); }

 private:
  static int clamped(double at, int count);

  Vec2 origin_ = Vec2::Zero();
  double cell_ = 1.0;
  int columns_ = 1;
  int rows_ = 1;
};

}  // namespace physltl::geometry
