#include "obstacle.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace physltl::knowledge {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// t with |origin + t * direction - center| < radius, direction of unit length.
Interval inside_disc(const geometry::Vec2& origin, const geometry::Vec2& direction, const geometry::Vec2& center,
                     double radius) {
  const geometry::Vec2 d = origin - center;
  const double b = direction.dot(d);
  const double discriminant = b * b - (d.squaredNorm() - radius * radius);
  if (discriminant <= 0.0) return {};
  const double root = std::sqrt(discriminant);
  return {-b - root, -b + root};
}

}  // namespace

// Clipping by one slab |origin_k + t * direction_k| < half_k per axis.
Interval inside_rectangle(const geometry::Vec2& origin, const geometry::Vec2& direction, const geometry::Vec2& half) {
  Interval t{-kInfinity, kInfinity};
  for (int k = 0; k < 2; ++k) {
    if (std::abs(direction[k]) < 1e-12) {
      if (std::abs(origin[k]) >= half[k]) return {};
      continue;
    }
    const double a = (-half[k] - origin[k]) / direction[k];
    const double b = (half[k] - origin[k]) / direction[k];
    t.lo = std::max(t.lo, std::min(a, b));
    t.hi = std::min(t.hi, std::max(a, b));
  }
  return t;
}

Obstacle::Obstacle(const geometry::OrientedBox& box)
    : center_(box.pose.position), axis_x_(box.axis(0)), axis_y_(box.axis(1)), half_extents_(box.half_extents) {}

double Obstacle::distance(const geometry::Vec2& p) const {
  const geometry::Vec2 outside = (local(p - center_).cwiseAbs() - half_extents_).cwiseMax(0.0);
  return outside.norm();
}

Interval Obstacle::closer_than(const geometry::Vec2& origin, const geometry::Vec2& direction, double radius) const {
  // The grown box is the union of two crossed rectangles and four corner discs; the line meets that
  // convex union in one interval, the hull of the pieces' intervals.
  const geometry::Vec2 o = local(origin - center_);
  const geometry::Vec2 u = local(direction);
  const geometry::Vec2& h = half_extents_;
  Interval hull{kInfinity, -kInfinity};
  auto include = [&hull](const Interval& piece) {
    if (piece.empty()) return;
    hull.lo = std::min(hull.lo, piece.lo);
    hull.hi = std::max(hull.hi, piece.hi);
  };
  include(inside_rectangle(o, u, {h.x() + radius, h.y()}));
  include(inside_rectangle(o, u, {h.x(), h.y() + radius}));
  for (const geometry::Vec2 corner : {geometry::Vec2(h.x(), h.y()), geometry::Vec2(-h.x(), h.y()),
                                      geometry::Vec2(h.x(), -h.y()), geometry::Vec2(-h.x(), -h.y())}) {
    include(inside_disc(o, u, corner, radius));
  }
  return hull;
}

}  // namespace physltl::knowledge
