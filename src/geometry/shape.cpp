#include "physltl/geometry/shape.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace physltl::geometry {
namespace {

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

Polygon counter_clockwise(Polygon p) {
  if (p.signed_area() < 0) std::reverse(p.vertices.begin(), p.vertices.end());
  return p;
}

double farthest_corner(const std::vector<Polygon>& parts) {
  double r = 0.0;
  for (const Polygon& p : parts) {
    for (const Vec2& v : p.vertices) r = std::max(r, v.norm());
  }
  return r;
}

double distance_to_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double length2 = d.squaredNorm();
  const double t = length2 > 0 ? std::clamp((p - a).dot(d) / length2, 0.0, 1.0) : 0.0;
  return (a + t * d - p).norm();
}

// A convex polygon, counter-clockwise: 0 inside or on it.
double distance_to_convex(const Polygon& polygon, const Vec2& p) {
  const auto& v = polygon.vertices;
  bool inside = true;
  for (size_t i = 0, j = v.size() - 1; i < v.size() && inside; j = i++) inside = cross(v[i] - v[j], p - v[j]) >= 0.0;
  if (inside) return 0.0;
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) best = std::min(best, distance_to_segment(p, v[j], v[i]));
  return best;
}

// Separating axes: the interiors of two convex polygons meet by more than `tolerance` along every edge
// normal of both.
bool convex_overlap(const Polygon& a, const Polygon& b, double tolerance) {
  for (const Polygon* p : {&a, &b}) {
    const auto& v = p->vertices;
    for (size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
      const Vec2 edge = v[i] - v[j];
      const double length = edge.norm();
      if (length == 0.0) continue;
      const Vec2 axis(-edge.y() / length, edge.x() / length);
      double a0 = std::numeric_limits<double>::infinity(), a1 = -a0, b0 = a0, b1 = -a0;
      for (const Vec2& x : a.vertices) a0 = std::min(a0, x.dot(axis)), a1 = std::max(a1, x.dot(axis));
      for (const Vec2& x : b.vertices) b0 = std::min(b0, x.dot(axis)), b1 = std::max(b1, x.dot(axis));
      if (std::min(a1, b1) - std::max(a0, b0) <= tolerance) return false;
    }
  }
  return true;
}

OrientedBox as_box(const Shape& shape, const Pose2& pose) { return {pose, shape.half_extents()}; }

Polygon regular_polygon(const Pose2& pose, double radius, CircleAs circle) {
  const double corner = circle == CircleAs::kInscribed ? radius : radius / std::cos(std::numbers::pi / kCircleCorners);
  Polygon p;
  for (int k = 0; k < kCircleCorners; ++k) {
    const double a = 2.0 * std::numbers::pi * k / kCircleCorners;
    p.vertices.push_back(pose.position + corner * Vec2(std::cos(a), std::sin(a)));
  }
  return p;
}

}  // namespace

Shape Shape::box(const Vec2& half_extents) {
  Shape s;
  s.kind_ = Kind::kBox;
  s.half_extents_ = half_extents;
  s.outline_ = Polygon::from_box({Pose2{}, half_extents});
  s.parts_ = {s.outline_};
  s.bound_radius_ = half_extents.norm();
  return s;
}

Shape Shape::circle(double radius) {
  Shape s;
  s.kind_ = Kind::kCircle;
  s.radius_ = radius;
  s.outline_ = {};
  s.parts_ = {};
  s.bound_radius_ = radius;
  return s;
}

Shape Shape::polygon(Polygon outline, std::vector<Polygon> parts) {
  Shape s;
  s.kind_ = Kind::kPolygon;
  s.outline_ = std::move(outline);
  for (Polygon& p : parts) s.parts_.push_back(counter_clockwise(std::move(p)));
  s.bound_radius_ = std::max(farthest_corner(s.parts_), farthest_corner({s.outline_}));
  return s;
}

double Shape::area() const {
  switch (kind_) {
    case Kind::kBox: return 4.0 * half_extents_.x() * half_extents_.y();
    case Kind::kCircle: return std::numbers::pi * radius_ * radius_;
    case Kind::kPolygon: break;
  }
  double a = 0.0;
  for (const Polygon& p : parts_) a += p.signed_area();
  return a;
}

double Shape::centre_clearance() const {
  switch (kind_) {
    case Kind::kBox: return half_extents_.minCoeff();
    case Kind::kCircle: return radius_;
    case Kind::kPolygon: break;
  }
  const auto& v = outline_.vertices;
  double nearest = std::numeric_limits<double>::infinity();
  for (size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) nearest = std::min(nearest, distance_to_segment(Vec2::Zero(), v[j], v[i]));
  return v.empty() ? 0.0 : nearest;
}

Vec2 to_world(const Pose2& pose, const Vec2& local) {
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  return pose.position + Vec2(c * local.x() - s * local.y(), s * local.x() + c * local.y());
}

Vec2 to_local(const Pose2& pose, const Vec2& world) {
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  const Vec2 d = world - pose.position;
  return {c * d.x() + s * d.y(), -s * d.x() + c * d.y()};
}

Polygon to_world(const Pose2& pose, const Polygon& local) {
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  Polygon out;
  out.vertices.reserve(local.vertices.size());
  for (const Vec2& v : local.vertices) out.vertices.push_back(pose.position + Vec2(c * v.x() - s * v.y(), s * v.x() + c * v.y()));
  return out;
}

double distance(const Shape& shape, const Pose2& pose, const Vec2& p) {
  switch (shape.kind()) {
    case Shape::Kind::kBox: return as_box(shape, pose).distance_to(p);
    case Shape::Kind::kCircle: return std::max(0.0, (p - pose.position).norm() - shape.radius());
    case Shape::Kind::kPolygon: break;
  }
  const Vec2 q = to_local(pose, p);
  double best = std::numeric_limits<double>::infinity();
  for (const Polygon& part : shape.parts()) best = std::min(best, distance_to_convex(part, q));
  return best;
}

bool overlap(const Shape& a, const Pose2& pose_a, const Shape& b, const Pose2& pose_b, double tolerance) {
  const double reach = a.bound_radius() + b.bound_radius() - tolerance;
  if ((pose_a.position - pose_b.position).squaredNorm() >= reach * reach) return false;
  if (a.is_box() && b.is_box()) return overlap(as_box(a, pose_a), as_box(b, pose_b), tolerance);
  if (a.kind() == Shape::Kind::kCircle) return overlap(b, pose_b, pose_a.position, a.radius(), tolerance);
  if (b.kind() == Shape::Kind::kCircle) return overlap(a, pose_a, pose_b.position, b.radius(), tolerance);
  const std::vector<Polygon> parts_a = convex_parts_at(a, pose_a, CircleAs::kInscribed);
  const std::vector<Polygon> parts_b = convex_parts_at(b, pose_b, CircleAs::kInscribed);
  for (const Polygon& pa : parts_a) {
    for (const Polygon& pb : parts_b) {
      if (convex_overlap(pa, pb, tolerance)) return true;
    }
  }
  return false;
}

bool overlap(const Shape& shape, const Pose2& pose, const Vec2& disc_center, double disc_radius, double tolerance) {
  if (shape.kind() == Shape::Kind::kCircle) {
    return (disc_center - pose.position).norm() < shape.radius() + disc_radius - tolerance;
  }
  return distance(shape, pose, disc_center) < disc_radius - tolerance;
}

bool inside(const Shape& shape, const Pose2& pose, const Rect& rect, double tolerance) {
  if (shape.is_box()) return inside(as_box(shape, pose), rect, tolerance);
  const Vec2 lo = rect.min - Vec2::Constant(tolerance), hi = rect.max + Vec2::Constant(tolerance);
  const Vec2& p = pose.position;
  const double r = shape.bound_radius();
  if ((p.array() - r >= lo.array()).all() && (p.array() + r <= hi.array()).all()) return true;
  if (shape.kind() == Shape::Kind::kCircle) return false;
  const Rect b = bounds(shape, pose);
  return (b.min.array() >= lo.array()).all() && (b.max.array() <= hi.array()).all();
}

Rect bounds(const Shape& shape, const Pose2& pose) {
  if (shape.is_box()) return Polygon::from_box(as_box(shape, pose)).bounds();
  if (shape.kind() == Shape::Kind::kCircle) {
    return {pose.position - Vec2::Constant(shape.radius()), pose.position + Vec2::Constant(shape.radius())};
  }
  Rect r{Vec2::Constant(std::numeric_limits<double>::infinity()), Vec2::Constant(-std::numeric_limits<double>::infinity())};
  for (const Polygon& part : shape.parts()) {
    for (const Vec2& v : part.vertices) {
      const Vec2 w = to_world(pose, v);
      r.min = r.min.cwiseMin(w), r.max = r.max.cwiseMax(w);
    }
  }
  return r;
}

std::vector<Polygon> convex_parts_at(const Shape& shape, const Pose2& pose, CircleAs circle) {
  if (shape.kind() == Shape::Kind::kCircle) return {regular_polygon(pose, shape.radius(), circle)};
  if (shape.is_box()) return {Polygon::from_box(as_box(shape, pose))};
  std::vector<Polygon> parts;
  parts.reserve(shape.parts().size());
  for (const Polygon& part : shape.parts()) parts.push_back(to_world(pose, part));
  return parts;
}

namespace {

// Each side of the convex, counter-clockwise polygon moved out by `by`; the corners where the moved sides meet.
Polygon mitred(const Polygon& p, double by) {
  const auto& v = p.vertices;
  const size_t n = v.size();
  Polygon out;
  for (size_t i = 0; i < n; ++i) {
    const Vec2 before = (v[i] - v[(i + n - 1) % n]).normalized(), after = (v[(i + 1) % n] - v[i]).normalized();
    const Vec2 n0(before.y(), -before.x()), n1(after.y(), -after.x());
    // The corner moves along the bisector, by `by` over the cosine of half the turn.
    const Vec2 bisector = (n0 + n1).normalized();
    out.vertices.push_back(v[i] + bisector * (by / std::max(bisector.dot(n1), 1e-6)));
  }
  return out;
}

}  // namespace

Shape grown(const Shape& shape, double by) {
  switch (shape.kind()) {
    case Shape::Kind::kBox: return Shape::box(shape.half_extents() + Vec2::Constant(by));
    case Shape::Kind::kCircle: return Shape::circle(shape.radius() + by);
    case Shape::Kind::kPolygon: break;
  }
  std::vector<Polygon> parts;
  for (const Polygon& part : shape.parts()) parts.push_back(mitred(part, by));
  const bool one_convex_outline = shape.parts().size() == 1 && !shape.outline().vertices.empty();
  return Shape::polygon(one_convex_outline ? parts.front() : Polygon{}, parts);
}

}  // namespace physltl::geometry
