// The geometry's table of shape kinds (shape_kinds.h): a box, a circle (an upright cylinder) and a
// polygon made of convex parts, each row's functions together.

#include "shape_kinds.h"

#include "physltl/geometry/free_space.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace physltl::geometry {
namespace {

double distance_to_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double length2 = d.squaredNorm();
  const double t = length2 > 0 ? std::clamp((p - a).dot(d) / length2, 0.0, 1.0) : 0.0;
  return (a + t * d - p).norm();
}

// A circle as a regular polygon whose corners lie on it (inscribed) or whose sides touch it.
Polygon regular_polygon(const Pose2& pose, double radius, CircleAs circle) {
  const double corner = circle == CircleAs::kInscribed ? radius : radius / std::cos(std::numbers::pi / kCircleCorners);
  Polygon p;
  for (int k = 0; k < kCircleCorners; ++k) {
    const double a = 2.0 * std::numbers::pi * k / kCircleCorners;
    p.vertices.push_back(pose.position + corner * Vec2(std::cos(a), std::sin(a)));
  }
  return p;
}

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

std::optional<double> no_disc(const Shape&) { return std::nullopt; }
// The shape itself outlines its parts: a box's and a polygon's.
bool contains_itself(const Shape& shape, const Pose2& pose, const Vec2& p, CircleAs) { return contains(shape, pose, p); }
std::optional<OrientedBox> no_box(const Shape&, const Pose2&) { return std::nullopt; }

// The convex parts' corners placed: a box's and a polygon's bounds.
Rect bounds_of_parts(const Shape& shape, const Pose2& pose) {
  Rect r{Vec2::Constant(std::numeric_limits<double>::infinity()), Vec2::Constant(-std::numeric_limits<double>::infinity())};
  for (const Polygon& part : shape.parts()) {
    for (const Vec2& v : part.vertices) {
      const Vec2 w = to_world(pose, v);
      r.min = r.min.cwiseMin(w), r.max = r.max.cwiseMax(w);
    }
  }
  return r;
}

// A box: a rectangle centred on the origin.
namespace box {

OrientedBox placed(const Shape& shape, const Pose2& pose) { return {pose, shape.half_extents()}; }

constexpr ShapeKindGeometry kRow{
    [](const Shape& s) { return 4.0 * s.half_extents().x() * s.half_extents().y(); },
    [](const Shape& s) { return s.half_extents().minCoeff(); },
    [](const Shape& s, const Pose2& pose, const Vec2& p) { return placed(s, pose).distance_to(p); },
    no_disc,
    [](const Shape& s, const Pose2& pose) { return std::optional<OrientedBox>(placed(s, pose)); },
    [](const Shape& s, const Pose2& pose) { return Polygon::from_box(placed(s, pose)).bounds(); },
    [](const Shape& s, const Pose2& pose, CircleAs) { return std::vector<Polygon>{Polygon::from_box(placed(s, pose))}; },
    contains_itself,
    [](const Shape& s, double by) { return Shape::box(s.half_extents() + Vec2::Constant(by)); },
    [](const Shape& s, const Pose2& pose, double radius) { return std::vector<Polygon>{grown_from_inside(placed(s, pose), radius)}; },
};

}  // namespace box

// A circle: an upright cylinder about its axis.
namespace circle {

constexpr ShapeKindGeometry kRow{
    [](const Shape& s) { return std::numbers::pi * s.radius() * s.radius(); },
    [](const Shape& s) { return s.radius(); },
    [](const Shape& s, const Pose2& pose, const Vec2& p) { return std::max(0.0, (p - pose.position).norm() - s.radius()); },
    [](const Shape& s) { return std::optional<double>(s.radius()); },
    no_box,
    [](const Shape& s, const Pose2& pose) {
      return Rect{pose.position - Vec2::Constant(s.radius()), pose.position + Vec2::Constant(s.radius())};
    },
    [](const Shape& s, const Pose2& pose, CircleAs as) { return std::vector<Polygon>{regular_polygon(pose, s.radius(), as)}; },
    [](const Shape& s, const Pose2& pose, const Vec2& p, CircleAs as) { return regular_polygon(pose, s.radius(), as).contains(p); },
    [](const Shape& s, double by) { return Shape::circle(s.radius() + by); },
    [](const Shape& s, const Pose2& pose, double radius) {
      return std::vector<Polygon>{regular_polygon(pose, s.radius() + radius, CircleAs::kInscribed)};
    },
};

}  // namespace circle

// A polygon: convex parts that tile it, its area centroid at the origin.
namespace polygon {

// 0 where the centre lies outside the outline (a concave body's centroid may: a chevron's, a thin L's).
double centre_clearance(const Shape& s) {
  const auto& v = s.outline().vertices;
  const bool centre_inside = std::any_of(s.parts().begin(), s.parts().end(), [](const Polygon& part) { return distance_to_convex(part, Vec2::Zero()) == 0.0; });
  if (!centre_inside) return 0.0;
  double nearest = std::numeric_limits<double>::infinity();
  for (size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) nearest = std::min(nearest, distance_to_segment(Vec2::Zero(), v[j], v[i]));
  return v.empty() ? 0.0 : nearest;
}

double distance(const Shape& s, const Pose2& pose, const Vec2& p) {
  const Vec2 q = to_local(pose, p);
  double best = std::numeric_limits<double>::infinity();
  for (const Polygon& part : s.parts()) best = std::min(best, distance_to_convex(part, q));
  return best;
}

std::vector<Polygon> parts_at(const Shape& s, const Pose2& pose, CircleAs) {
  std::vector<Polygon> parts;
  parts.reserve(s.parts().size());
  for (const Polygon& part : s.parts()) parts.push_back(to_world(pose, part));
  return parts;
}

Shape grown(const Shape& s, double by) {
  std::vector<Polygon> parts;
  for (const Polygon& part : s.parts()) parts.push_back(mitred(part, by));
  const bool one_convex_outline = s.parts().size() == 1 && !s.outline().vertices.empty();
  return Shape::polygon(one_convex_outline ? parts.front() : Polygon{}, parts);
}

// Each convex part with an arc of chords round each corner.
std::vector<Polygon> grown_from_inside(const Shape& s, const Pose2& pose, double radius) {
  constexpr int kChordsPerCorner = 2;
  std::vector<Polygon> grown;
  for (const Polygon& part : parts_at(s, pose, CircleAs::kInscribed)) {
    const auto& v = part.vertices;  // counter-clockwise
    const size_t n = v.size();
    Polygon g;
    for (size_t i = 0; i < n; ++i) {
      // The arc round corner i, from the outward normal of the side before to that of the side after.
      const Vec2 before = v[i] - v[(i + n - 1) % n], after = v[(i + 1) % n] - v[i];
      const double from = std::atan2(-before.x(), before.y()), turn = std::remainder(std::atan2(-after.x(), after.y()) - from, 2 * std::numbers::pi);
      for (int k = 0; k <= kChordsPerCorner; ++k) {
        const double a = from + turn * k / kChordsPerCorner;
        g.vertices.push_back(v[i] + radius * Vec2(std::cos(a), std::sin(a)));
      }
    }
    grown.push_back(std::move(g));
  }
  return grown;
}

constexpr ShapeKindGeometry kRow{
    [](const Shape& s) {
      double a = 0.0;
      for (const Polygon& p : s.parts()) a += p.signed_area();
      return a;
    },
    centre_clearance, distance, no_disc, no_box, bounds_of_parts, parts_at, contains_itself, grown, grown_from_inside,
};

}  // namespace polygon

// Shape::Kind order.
constexpr std::array<const ShapeKindGeometry*, 3> kKinds = {&box::kRow, &circle::kRow, &polygon::kRow};

}  // namespace

double distance_to_convex(const Polygon& polygon, const Vec2& p) {
  const auto& v = polygon.vertices;
  bool inside = true;
  for (size_t i = 0, j = v.size() - 1; i < v.size() && inside; j = i++) inside = cross(v[i] - v[j], p - v[j]) >= 0.0;
  if (inside) return 0.0;
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) best = std::min(best, distance_to_segment(p, v[j], v[i]));
  return best;
}

const ShapeKindGeometry& kind_of(const Shape& shape) { return *kKinds[static_cast<std::size_t>(shape.kind())]; }

}  // namespace physltl::geometry
