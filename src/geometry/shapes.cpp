#include "physltl/geometry/shapes.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace physltl::geometry {
namespace {

// Orientation of c relative to the directed line a->b, with a relative dead band.
int orientation(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double v = cross(b - a, c - a);
  const double scale = std::max({(b - a).norm(), (c - a).norm(), 1.0});
  const double eps = 1e-12 * scale * scale;
  return v > eps ? 1 : (v < -eps ? -1 : 0);
}

// Segments cross at a single point interior to both (touching or collinear overlap is not crossing).
bool segments_cross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const int o1 = orientation(a, b, c), o2 = orientation(a, b, d);
  const int o3 = orientation(c, d, a), o4 = orientation(c, d, b);
  return o1 * o2 < 0 && o3 * o4 < 0;
}

bool segments_meet(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  auto on_segment = [](const Vec2& p, const Vec2& q, const Vec2& r) {
    return std::min(p.x(), q.x()) - 1e-12 <= r.x() && r.x() <= std::max(p.x(), q.x()) + 1e-12 &&
           std::min(p.y(), q.y()) - 1e-12 <= r.y() && r.y() <= std::max(p.y(), q.y()) + 1e-12;
  };
  const int o1 = orientation(a, b, c), o2 = orientation(a, b, d);
  const int o3 = orientation(c, d, a), o4 = orientation(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && on_segment(a, b, c)) || (o2 == 0 && on_segment(a, b, d)) ||
         (o3 == 0 && on_segment(c, d, a)) || (o4 == 0 && on_segment(c, d, b));
}

// Strictly inside: not on the boundary.
bool strictly_contains(const Polygon& poly, const Vec2& p) {
  const auto& v = poly.vertices;
  for (size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
    if (segments_meet(v[j], v[i], p, p)) return false;
  }
  return poly.contains(p);
}

// Projection interval of a box onto a unit axis.
std::pair<double, double> project(const OrientedBox& b, const Vec2& axis) {
  const double c = b.pose.position.dot(axis);
  const double r = std::abs(b.axis(0).dot(axis)) * b.half_extents.x() +
                   std::abs(b.axis(1).dot(axis)) * b.half_extents.y();
  return {c - r, c + r};
}

}  // namespace

bool Rect::contains(const Vec2& p) const {
  return p.x() >= min.x() && p.x() <= max.x() && p.y() >= min.y() && p.y() <= max.y();
}

Vec2 OrientedBox::axis(int i) const {
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  return i == 0 ? Vec2(c, s) : Vec2(-s, c);
}

std::array<Vec2, 4> OrientedBox::corners() const {
  const Vec2 ex = axis(0) * half_extents.x(), ey = axis(1) * half_extents.y();
  const Vec2& c = pose.position;
  return {c - ex - ey, c + ex - ey, c + ex + ey, c - ex + ey};
}

bool OrientedBox::contains(const Vec2& p) const { return distance_to(p) == 0.0; }

double OrientedBox::distance_to(const Vec2& p) const {
  const Vec2 d = p - pose.position;
  const Vec2 local(d.dot(axis(0)), d.dot(axis(1)));
  const Vec2 outside = (local.cwiseAbs() - half_extents).cwiseMax(0.0);
  return outside.norm();
}

Polygon Polygon::from_rect(const Rect& r) {
  return {{r.min, Vec2(r.max.x(), r.min.y()), r.max, Vec2(r.min.x(), r.max.y())}};
}

Polygon Polygon::from_box(const OrientedBox& b) {
  const auto c = b.corners();
  return {{c.begin(), c.end()}};
}

double Polygon::signed_area() const {
  double a = 0.0;
  for (size_t i = 0, j = vertices.size() - 1; i < vertices.size(); j = i++) a += cross(vertices[j], vertices[i]);
  return 0.5 * a;
}

Vec2 Polygon::centroid() const {
  const double a = signed_area();
  Vec2 c = Vec2::Zero();
  if (std::abs(a) < 1e-15) {
    for (const auto& v : vertices) c += v;
    return c / static_cast<double>(std::max<size_t>(vertices.size(), 1));
  }
  for (size_t i = 0, j = vertices.size() - 1; i < vertices.size(); j = i++) {
    c += (vertices[j] + vertices[i]) * cross(vertices[j], vertices[i]);
  }
  return c / (6.0 * a);
}

Rect Polygon::bounds() const {
  Rect r{Vec2::Constant(std::numeric_limits<double>::infinity()),
         Vec2::Constant(-std::numeric_limits<double>::infinity())};
  for (const auto& v : vertices) {
    r.min = r.min.cwiseMin(v);
    r.max = r.max.cwiseMax(v);
  }
  return r;
}

bool Polygon::contains(const Vec2& p) const {
  bool in = false;
  for (size_t i = 0, j = vertices.size() - 1; i < vertices.size(); j = i++) {
    const Vec2 &a = vertices[j], &b = vertices[i];
    if (segments_meet(a, b, p, p)) return true;
    if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y())) {
      in = !in;
    }
  }
  return in;
}

bool Polygon::is_simple() const {
  const size_t n = vertices.size();
  if (n < 3) return false;
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = i + 1; j < n; ++j) {
      const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      if (adjacent) continue;
      if (segments_meet(vertices[i], vertices[(i + 1) % n], vertices[j], vertices[(j + 1) % n])) return false;
    }
  }
  return std::abs(signed_area()) > 1e-12;
}

bool overlap(const OrientedBox& a, const OrientedBox& b, double tolerance) {
  for (const Vec2& axis : {a.axis(0), a.axis(1), b.axis(0), b.axis(1)}) {
    const auto [a0, a1] = project(a, axis);
    const auto [b0, b1] = project(b, axis);
    if (std::min(a1, b1) - std::max(a0, b0) <= tolerance) return false;
  }
  return true;
}

bool overlap(const Polygon& a, const Polygon& b) {
  const auto& va = a.vertices;
  const auto& vb = b.vertices;
  for (size_t i = 0, j = va.size() - 1; i < va.size(); j = i++) {
    for (size_t k = 0, l = vb.size() - 1; k < vb.size(); l = k++) {
      if (segments_cross(va[j], va[i], vb[l], vb[k])) return true;
    }
  }
  // No proper crossing: the interiors meet only if one polygon has a vertex, an edge midpoint or its
  // centroid strictly inside the other (the centroid catches identical polygons).
  auto pokes_into = [](const Polygon& p, const Polygon& q) {
    const auto& v = p.vertices;
    for (size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
      if (strictly_contains(q, v[i]) || strictly_contains(q, 0.5 * (v[i] + v[j]))) return true;
    }
    return strictly_contains(q, p.centroid()) && p.contains(p.centroid());
  };
  return pokes_into(a, b) || pokes_into(b, a);
}

bool overlap(const OrientedBox& box, const Vec2& disc_center, double disc_radius, double tolerance) {
  return box.distance_to(disc_center) < disc_radius - tolerance;
}

bool inside(const OrientedBox& box, const Rect& rect, double tolerance) {
  // The validity checker asks this for every box at every physics step: first the circle around the box,
  // which needs no trigonometry, then the box's own bounds.
  const Vec2 lo = rect.min - Vec2::Constant(tolerance), hi = rect.max + Vec2::Constant(tolerance);
  const Vec2& p = box.pose.position;
  const double radius = box.half_extents.norm();
  if ((p.array() - radius >= lo.array()).all() && (p.array() + radius <= hi.array()).all()) return true;
  const double c = std::abs(std::cos(box.pose.yaw)), s = std::abs(std::sin(box.pose.yaw));
  const Vec2 half(c * box.half_extents.x() + s * box.half_extents.y(), s * box.half_extents.x() + c * box.half_extents.y());
  return ((p - half).array() >= lo.array()).all() && ((p + half).array() <= hi.array()).all();
}

bool inside(const Polygon& polygon, const Rect& rect, double tolerance) {
  const Rect b = polygon.bounds();
  return b.min.x() >= rect.min.x() - tolerance && b.min.y() >= rect.min.y() - tolerance &&
         b.max.x() <= rect.max.x() + tolerance && b.max.y() <= rect.max.y() + tolerance;
}

}  // namespace physltl::geometry
