#pragma once
// Where the centre of a disc can go among obstacles of any shape inside a rectangle, on a grid, and how far it is
// from every place to a set of target places: the way a body's centre must travel to reach a region.
//
// Sound by construction, for "it cannot get there" conclusions: a cell counts as free when its centre
// keeps the disc's radius less half a cell diagonal from every obstacle and the rectangle's edge, so any
// place the real disc can reach lies in a free cell, and any continuous way it can take runs through
// 8-connected free cells. Distances are along those cells (8-connected, diagonal steps sqrt(2) cells).

#include "physltl/base/deadline.h"
#include "physltl/geometry/shape.h"
#include "physltl/geometry/uniform_grid.h"

#include <limits>
#include <span>
#include <vector>

namespace physltl::geometry {

class DiscField {
 public:
  static constexpr double kUnreachable = std::numeric_limits<double>::infinity();

  // `cell`: the grid's cell edge, in metres. A field has up to millions of cells: the constructor and
  // compute_distances check `deadline` as they go and throw DeadlineReached.
  DiscField(const Rect& bounds, double cell, double radius, std::span<const Footprint> obstacles, const base::Deadline& deadline = {});

  // One flag a cell: whether its centre lies within `within` metres of one of `regions` (inside one, when
  // 0). Each region's cells are found from its bounding box, so the cost grows with the regions' area, not
  // with cells times regions (a level of 250 goals has 250 regions).
  std::vector<bool> cells_near(std::span<const Polygon* const> regions, double within, const base::Deadline& deadline = {}) const;
  // Distances to the free cells `targets` marks (one flag a cell, as cells_near gives), by Dijkstra over
  // the free cells.
  void compute_distances(const std::vector<bool>& targets, const base::Deadline& deadline = {});
  // Distance from the cell of `p` to the nearest target (0 in a target cell); kUnreachable when the cell
  // is not free or no target is connected to it.
  double distance(const Vec2& p) const;
  // Whether a target cell is connected to the cell of `p`.
  bool reaches_target(const Vec2& p) const { return distance(p) < kUnreachable; }
  // The point about `ahead` metres further along a shortest way from `p` to the targets (steepest descent
  // of the distances); `p` itself when it stands in a target or nowhere useful.
  Vec2 ahead_of(const Vec2& p, double ahead) const;
  // The free cell whose centre is nearest to `p` within `search` metres, as a point; `p` when none is.
  Vec2 nearest_free(const Vec2& p, double search) const;

  double cell() const { return grid_.cell(); }

 private:
  UniformGrid grid_;
  std::vector<bool> free_;
  std::vector<double> distance_;
};

}  // namespace physltl::geometry
