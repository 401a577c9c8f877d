#include "physltl/geometry/disc_field.h"

#include "physltl/geometry/free_space.h"
#include "physltl/geometry/shortest_paths.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace physltl::geometry {
namespace {

constexpr double kSqrt2 = 1.4142135623730951;
constexpr int kCellsBetweenChecks = 4096;  // of the deadline: a fraction of a millisecond of work

}  // namespace

DiscField::DiscField(const Rect& bounds, double cell, double radius, std::span<const Footprint> obstacles,
                     const base::Deadline& deadline)
    : grid_(UniformGrid::covering(bounds, cell)), free_(grid_.size(), true), distance_(free_.size(), kUnreachable) {
  const double clearance = radius - cell * kSqrt2 / 2;  // less half a diagonal: see the header
  const Rect inner{bounds.min + Vec2::Constant(clearance), bounds.max - Vec2::Constant(clearance)};
  for (int iy = 0; iy < grid_.rows(); ++iy) {
    if (iy % 64 == 0) deadline.check();
    for (int ix = 0; ix < grid_.columns(); ++ix) free_[grid_.index(ix, iy)] = clearance <= 0 || inner.contains(grid_.centre(ix, iy));
  }
  for (const Footprint& obstacle : obstacles) {
    deadline.check();
    // Only the cells near the obstacle can be within reach of it.
    const Vec2& at = obstacle.pose.position;
    const double reach = obstacle.shape.bound_radius() + std::max(clearance, 0.0);
    const int x0 = grid_.column(at.x() - reach), x1 = grid_.column(at.x() + reach);
    const int y0 = grid_.row(at.y() - reach), y1 = grid_.row(at.y() + reach);
    for (int iy = y0; iy <= y1; ++iy) {
      for (int ix = x0; ix <= x1; ++ix) {
        const double d = geometry::distance(obstacle.shape, obstacle.pose, grid_.centre(ix, iy));
        if (d < std::max(clearance, 0.0) || d == 0.0) free_[grid_.index(ix, iy)] = false;
      }
    }
  }
}

std::vector<bool> DiscField::cells_near(std::span<const Polygon* const> regions, double within, const base::Deadline& deadline) const {
  std::vector<bool> near(free_.size(), false);
  for (const Polygon* region : regions) {
    deadline.check();
    const Rect box = region->bounds();
    const int x0 = grid_.column(box.min.x() - within), x1 = grid_.column(box.max.x() + within);
    const int y0 = grid_.row(box.min.y() - within), y1 = grid_.row(box.max.y() + within);
    for (int iy = y0; iy <= y1; ++iy) {
      for (int ix = x0; ix <= x1; ++ix) {
        const std::size_t i = grid_.index(ix, iy);
        if (near[i]) continue;
        const Vec2 centre = grid_.centre(ix, iy);
        near[i] = within > 0.0 ? geometry::distance(centre, *region) <= within : region->contains(centre);
      }
    }
  }
  return near;
}

void DiscField::compute_distances(const std::vector<bool>& targets, const base::Deadline& deadline) {
  ShortestPaths ways(free_.size());
  for (std::size_t i = 0; i < free_.size(); ++i) {
    if (free_[i] && targets[i]) ways.seed(static_cast<int>(i), 0.0);
  }
  int settled = 0;
  ways.run([&](int i, double d) {
    if (++settled % kCellsBetweenChecks == 0) deadline.check();
    const int ix = grid_.column_of(static_cast<std::size_t>(i)), iy = grid_.row_of(static_cast<std::size_t>(i));
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int jx = ix + dx, jy = iy + dy;
        if ((dx == 0 && dy == 0) || !grid_.contains(jx, jy)) continue;
        const std::size_t j = grid_.index(jx, jy);
        if (!free_[j]) continue;
        // A diagonal step passes between its two side cells: both must be free, or it cuts a corner.
        if (dx != 0 && dy != 0 && (!free_[grid_.index(ix + dx, iy)] || !free_[grid_.index(ix, iy + dy)])) continue;
        ways.relax(i, static_cast<int>(j), d + grid_.cell() * (dx != 0 && dy != 0 ? kSqrt2 : 1.0));
      }
    }
    return true;
  });
  distance_ = ways.distances();
}

double DiscField::distance(const Vec2& p) const { return distance_[grid_.index_of(p)]; }

Vec2 DiscField::nearest_free(const Vec2& p, double search) const {
  const int reach = static_cast<int>(std::ceil(search / grid_.cell()));
  const int cx = grid_.column(p.x()), cy = grid_.row(p.y());
  Vec2 best = p;
  double best_distance = kUnreachable;
  for (int iy = std::max(0, cy - reach); iy <= std::min(grid_.rows() - 1, cy + reach); ++iy) {
    for (int ix = std::max(0, cx - reach); ix <= std::min(grid_.columns() - 1, cx + reach); ++ix) {
      const Vec2 centre = grid_.centre(ix, iy);
      const double d = (centre - p).norm();
      const std::size_t i = grid_.index(ix, iy);
      if (free_[i] && distance_[i] < kUnreachable && d < best_distance) best = centre, best_distance = d;
    }
  }
  return best;
}

Vec2 DiscField::ahead_of(const Vec2& p, double ahead) const {
  int ix = grid_.column(p.x()), iy = grid_.row(p.y());
  if (distance_[grid_.index(ix, iy)] == kUnreachable) return p;
  for (double travelled = 0.0; travelled < ahead && distance_[grid_.index(ix, iy)] > 0.0;) {
    int best_x = ix, best_y = iy;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int jx = ix + dx, jy = iy + dy;
        if (!grid_.contains(jx, jy)) continue;
        if (distance_[grid_.index(jx, jy)] < distance_[grid_.index(best_x, best_y)]) best_x = jx, best_y = jy;
      }
    }
    if (best_x == ix && best_y == iy) break;
    travelled += grid_.cell() * ((best_x != ix && best_y != iy) ? kSqrt2 : 1.0);
    ix = best_x, iy = best_y;
  }
  return grid_.centre(ix, iy);
}

}  // namespace physltl::geometry
