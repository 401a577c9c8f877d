#include "obstacle.h"

#include "shape_kinds.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace physltl::knowledge {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

}  // namespace

Interval inside_disc(const geometry::Vec2& origin, const geometry::Vec2& direction, const geometry::Vec2& center,
                     double radius) {
  const geometry::Vec2 d = origin - center;
  const double b = direction.dot(d);
  const double discriminant = b * b - (d.squaredNorm() - radius * radius);
  if (discriminant <= 0.0) return {};
  const double root = std::sqrt(discriminant);
  return {-b - root, -b + root};
}

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

Interval inside_convex(const geometry::Vec2& origin, const geometry::Vec2& direction, const std::vector<geometry::Vec2>& v) {
  Interval t{-kInfinity, kInfinity};
  for (size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
    const geometry::Vec2 edge = v[i] - v[j];
    const double at_origin = edge.x() * (origin.y() - v[j].y()) - edge.y() * (origin.x() - v[j].x());  // > 0 inside
    const double slope = edge.x() * direction.y() - edge.y() * direction.x();
    if (slope == 0.0) {
      if (at_origin <= 0.0) return {};
    } else if (slope > 0.0) {
      t.lo = std::max(t.lo, -at_origin / slope);
    } else {
      t.hi = std::min(t.hi, -at_origin / slope);
    }
    if (t.empty()) return {};
  }
  return t;
}

Obstacle::Obstacle(const geometry::Shape& shape, const geometry::Pose2& pose)
    : shape_(shape),
      pose_(pose),
      center_(pose.position),
      axis_x_(std::cos(pose.yaw), std::sin(pose.yaw)),
      axis_y_(-std::sin(pose.yaw), std::cos(pose.yaw)) {}

double Obstacle::distance(const geometry::Vec2& p) const { return kind_of(shape_).distance(*this, p); }

void Obstacle::closer_than(const geometry::Vec2& origin, const geometry::Vec2& direction, double radius,
                           std::vector<Interval>& out) const {
  kind_of(shape_).closer_than(*this, origin, direction, radius, out);
}

}  // namespace physltl::knowledge
