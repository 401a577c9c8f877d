#include "physltl/geometry/shape.h"

#include "shape_kinds.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace physltl::geometry {
namespace {

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

double Shape::area() const { return kind_of(*this).area(*this); }

double Shape::centre_clearance() const { return kind_of(*this).centre_clearance(*this); }

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

double distance(const Shape& shape, const Pose2& pose, const Vec2& p) { return kind_of(shape).distance(shape, pose, p); }

bool overlap(const Shape& a, const Pose2& pose_a, const Shape& b, const Pose2& pose_b, double tolerance) {
  const double reach = a.bound_radius() + b.bound_radius() - tolerance;
  if ((pose_a.position - pose_b.position).squaredNorm() >= reach * reach) return false;
  const auto box_a = kind_of(a).oriented_box(a, pose_a), box_b = kind_of(b).oriented_box(b, pose_b);
  if (box_a && box_b) return overlap(*box_a, *box_b, tolerance);
  if (const auto radius = kind_of(a).disc_radius(a)) return overlap(b, pose_b, pose_a.position, *radius, tolerance);
  if (const auto radius = kind_of(b).disc_radius(b)) return overlap(a, pose_a, pose_b.position, *radius, tolerance);
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
  if (const auto radius = kind_of(shape).disc_radius(shape)) return (disc_center - pose.position).norm() < *radius + disc_radius - tolerance;
  return distance(shape, pose, disc_center) < disc_radius - tolerance;
}

bool inside(const Shape& shape, const Pose2& pose, const Rect& rect, double tolerance) {
  if (const auto box = kind_of(shape).oriented_box(shape, pose)) return inside(*box, rect, tolerance);
  const Vec2 lo = rect.min - Vec2::Constant(tolerance), hi = rect.max + Vec2::Constant(tolerance);
  const Vec2& p = pose.position;
  const double r = shape.bound_radius();
  if ((p.array() - r >= lo.array()).all() && (p.array() + r <= hi.array()).all()) return true;
  const Rect b = bounds(shape, pose);
  return (b.min.array() >= lo.array()).all() && (b.max.array() <= hi.array()).all();
}

Rect bounds(const Shape& shape, const Pose2& pose) { return kind_of(shape).bounds(shape, pose); }

std::vector<Polygon> convex_parts_at(const Shape& shape, const Pose2& pose, CircleAs circle) {
  return kind_of(shape).convex_parts_at(shape, pose, circle);
}

bool contains_as_parts(const Shape& shape, const Pose2& pose, const Vec2& p, CircleAs circle) {
  return kind_of(shape).contains_as_parts(shape, pose, p, circle);
}

Shape grown(const Shape& shape, double by) { return kind_of(shape).grown(shape, by); }

}  // namespace physltl::geometry
