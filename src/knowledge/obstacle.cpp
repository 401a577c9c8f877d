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

namespace {

// t with origin + t * direction strictly inside the convex, counter-clockwise polygon (Cyrus-Beck).
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

// The convex polygon grown by a disc is the polygon, a rectangle outside each side and a disc at each
// corner; the line meets that convex union in one interval, the hull of the pieces' intervals.
Interval grown_convex(const geometry::Vec2& origin, const geometry::Vec2& direction, const geometry::Polygon& part,
                      double radius) {
  Interval hull{kInfinity, -kInfinity};
  auto include = [&hull](const Interval& piece) {
    if (piece.empty()) return;
    hull.lo = std::min(hull.lo, piece.lo);
    hull.hi = std::max(hull.hi, piece.hi);
  };
  const auto& v = part.vertices;
  include(inside_convex(origin, direction, v));
  for (size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
    const geometry::Vec2 edge = v[i] - v[j];
    const double length = edge.norm();
    if (length == 0.0) continue;
    const geometry::Vec2 out = radius * geometry::Vec2(edge.y(), -edge.x()) / length;
    include(inside_convex(origin, direction, {v[j], v[j] + out, v[i] + out, v[i]}));
    include(inside_disc(origin, direction, v[i], radius));
  }
  return hull;
}

}  // namespace

Obstacle::Obstacle(const geometry::Shape& shape, const geometry::Pose2& pose)
    : shape_(shape),
      pose_(pose),
      center_(pose.position),
      axis_x_(std::cos(pose.yaw), std::sin(pose.yaw)),
      axis_y_(-std::sin(pose.yaw), std::cos(pose.yaw)) {}

double Obstacle::distance(const geometry::Vec2& p) const {
  if (shape_.is_box()) {
    const geometry::Vec2 outside = (local(p - center_).cwiseAbs() - shape_.half_extents()).cwiseMax(0.0);
    return outside.norm();
  }
  return geometry::distance(shape_, pose_, p);
}

void Obstacle::closer_than(const geometry::Vec2& origin, const geometry::Vec2& direction, double radius,
                           std::vector<Interval>& out) const {
  const auto keep = [&out](const Interval& t) {
    if (!t.empty()) out.push_back(t);
  };
  switch (shape_.kind()) {
    case geometry::Shape::Kind::kBox: return keep(box_closer_than(origin, direction, radius));
    case geometry::Shape::Kind::kCircle: return keep(inside_disc(origin, direction, center_, shape_.radius() + radius));
    case geometry::Shape::Kind::kPolygon: break;
  }
  // In the body's frame: the parts are kept there.
  const geometry::Vec2 o = local(origin - center_), u = local(direction);
  for (const geometry::Polygon& part : shape_.parts()) keep(grown_convex(o, u, part, radius));
}

Interval Obstacle::box_closer_than(const geometry::Vec2& origin, const geometry::Vec2& direction, double radius) const {
  // The grown box is the union of two crossed rectangles and four corner discs; the line meets that
  // convex union in one interval, the hull of the pieces' intervals.
  const geometry::Vec2 o = local(origin - center_);
  const geometry::Vec2 u = local(direction);
  const geometry::Vec2& h = shape_.half_extents();
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
