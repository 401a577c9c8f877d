#include "physltl/geometry/disc_field.h"

#include <algorithm>
#include <cmath>
#include <queue>
#include <utility>

namespace physltl::geometry {
namespace {

constexpr double kSqrt2 = 1.4142135623730951;

}  // namespace

DiscField::DiscField(const Rect& bounds, double cell, double radius, std::span<const Footprint> obstacles)
    : origin_(bounds.min),
      cell_(cell),
      nx_(std::max(1, static_cast<int>(std::ceil(bounds.size().x() / cell)))),
      ny_(std::max(1, static_cast<int>(std::ceil(bounds.size().y() / cell)))),
      free_(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_), true),
      distance_(free_.size(), kUnreachable) {
  const double clearance = radius - cell * kSqrt2 / 2;  // less half a diagonal: see the header
  const Rect inner{bounds.min + Vec2::Constant(clearance), bounds.max - Vec2::Constant(clearance)};
  for (int iy = 0; iy < ny_; ++iy) {
    for (int ix = 0; ix < nx_; ++ix) free_[index(ix, iy)] = clearance <= 0 || inner.contains(centre(ix, iy));
  }
  for (const Footprint& obstacle : obstacles) {
    // Only the cells near the obstacle can be within reach of it.
    const Vec2& at = obstacle.pose.position;
    const double reach = obstacle.shape.bound_radius() + std::max(clearance, 0.0);
    const int x0 = column(at.x() - reach), x1 = column(at.x() + reach);
    const int y0 = row(at.y() - reach), y1 = row(at.y() + reach);
    for (int iy = y0; iy <= y1; ++iy) {
      for (int ix = x0; ix <= x1; ++ix) {
        const double d = geometry::distance(obstacle.shape, obstacle.pose, centre(ix, iy));
        if (d < std::max(clearance, 0.0) || d == 0.0) free_[index(ix, iy)] = false;
      }
    }
  }
}

int DiscField::column(double x) const { return std::clamp(static_cast<int>(std::floor((x - origin_.x()) / cell_)), 0, nx_ - 1); }
int DiscField::row(double y) const { return std::clamp(static_cast<int>(std::floor((y - origin_.y()) / cell_)), 0, ny_ - 1); }

void DiscField::compute_distances(const std::function<bool(const Vec2& centre, double half_edge)>& is_target) {
  std::fill(distance_.begin(), distance_.end(), kUnreachable);
  using Entry = std::pair<double, std::size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  for (int iy = 0; iy < ny_; ++iy) {
    for (int ix = 0; ix < nx_; ++ix) {
      const std::size_t i = index(ix, iy);
      if (free_[i] && is_target(centre(ix, iy), cell_ / 2)) distance_[i] = 0.0, open.push({0.0, i});
    }
  }
  while (!open.empty()) {
    const auto [d, i] = open.top();
    open.pop();
    if (d > distance_[i]) continue;
    const int ix = static_cast<int>(i % static_cast<std::size_t>(nx_)), iy = static_cast<int>(i / static_cast<std::size_t>(nx_));
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int jx = ix + dx, jy = iy + dy;
        if ((dx == 0 && dy == 0) || jx < 0 || jy < 0 || jx >= nx_ || jy >= ny_) continue;
        const std::size_t j = index(jx, jy);
        if (!free_[j]) continue;
        // A diagonal step passes between its two side cells: both must be free, or it cuts a corner.
        if (dx != 0 && dy != 0 && (!free_[index(ix + dx, iy)] || !free_[index(ix, iy + dy)])) continue;
        const double next = d + cell_ * (dx != 0 && dy != 0 ? kSqrt2 : 1.0);
        if (next < distance_[j]) distance_[j] = next, open.push({next, j});
      }
    }
  }
}

double DiscField::distance(const Vec2& p) const { return distance_[index(column(p.x()), row(p.y()))]; }

Vec2 DiscField::nearest_free(const Vec2& p, double search) const {
  const int reach = static_cast<int>(std::ceil(search / cell_));
  const int cx = column(p.x()), cy = row(p.y());
  Vec2 best = p;
  double best_distance = kUnreachable;
  for (int iy = std::max(0, cy - reach); iy <= std::min(ny_ - 1, cy + reach); ++iy) {
    for (int ix = std::max(0, cx - reach); ix <= std::min(nx_ - 1, cx + reach); ++ix) {
      const double d = (centre(ix, iy) - p).norm();
      if (free_[index(ix, iy)] && distance_[index(ix, iy)] < kUnreachable && d < best_distance) best = centre(ix, iy), best_distance = d;
    }
  }
  return best;
}

Vec2 DiscField::ahead_of(const Vec2& p, double ahead) const {
  int ix = column(p.x()), iy = row(p.y());
  if (distance_[index(ix, iy)] == kUnreachable) return p;
  for (double travelled = 0.0; travelled < ahead && distance_[index(ix, iy)] > 0.0;) {
    int best_x = ix, best_y = iy;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int jx = ix + dx, jy = iy + dy;
        if (jx < 0 || jy < 0 || jx >= nx_ || jy >= ny_) continue;
        if (distance_[index(jx, jy)] < distance_[index(best_x, best_y)]) best_x = jx, best_y = jy;
      }
    }
    if (best_x == ix && best_y == iy) break;
    travelled += cell_ * ((best_x != ix && best_y != iy) ? kSqrt2 : 1.0);
    ix = best_x, iy = best_y;
  }
  return centre(ix, iy);
}

}  // namespace physltl::geometry
