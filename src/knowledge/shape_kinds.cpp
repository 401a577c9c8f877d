// The knowledge's table of shape kinds (shape_kinds.h): each kind's faces as mRegions, and how the robot
// meets it where it stands.

#include "shape_kinds.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace physltl::knowledge {
namespace {

using geometry::Vec2;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The hull of the intervals it is given: where a line meets a convex union of pieces.
struct Hull {
  Interval interval{kInfinity, -kInfinity};
  void include(const Interval& piece) {
    if (piece.empty()) return;
    interval.lo = std::min(interval.lo, piece.lo);
    interval.hi = std::max(interval.hi, piece.hi);
  }
};

void keep(const Interval& t, std::vector<Interval>& out) {
  if (!t.empty()) out.push_back(t);
}

Vec2 outward_normal(scenario::Side side) {
  switch (side) {
    case scenario::Side::kMinusX: return {-1.0, 0.0};
    case scenario::Side::kPlusX: return {1.0, 0.0};
    case scenario::Side::kMinusY: return {0.0, -1.0};
    case scenario::Side::kPlusY: return {0.0, 1.0};
  }
  return {0.0, 0.0};
}

bool is_x_side(scenario::Side side) { return side == scenario::Side::kMinusX || side == scenario::Side::kPlusX; }

// A box's side: the strip and the contact segment along the body's own axes.
MRegionTemplate box_side(scenario::Side side, const Vec2& half_extents, double depth, double robot_radius) {
  const Vec2 normal = outward_normal(side);
  const Vec2 tangent(-normal.y(), normal.x());
  const double to_side = is_x_side(side) ? half_extents.x() : half_extents.y();
  const double half_length = is_x_side(side) ? half_extents.y() : half_extents.x();
  MRegionTemplate m;
  m.face = static_cast<int>(side);
  m.strip.pose.position = normal * (to_side + 0.5 * depth);
  m.strip.half_extents = is_x_side(side) ? Vec2(0.5 * depth, half_length) : Vec2(half_length, 0.5 * depth);
  const Vec2 touching = normal * (to_side + robot_radius);
  m.contact_from = touching - tangent * half_length;
  m.contact_to = touching + tangent * half_length;
  m.push = -normal;
  return m;
}

// A straight face from `a` to `b` whose outside is towards `normal` (of unit length).
MRegionTemplate straight_face(int face, const Vec2& a, const Vec2& b, const Vec2& normal, double depth,
                              double robot_radius) {
  const Vec2 along = b - a;
  const double half_length = 0.5 * along.norm();
  const Vec2 tangent = along / (2.0 * half_length);
  const Vec2 middle = 0.5 * (a + b);
  MRegionTemplate m;
  m.face = face;
  m.strip.pose = {middle + normal * (0.5 * depth), std::atan2(tangent.y(), tangent.x())};
  m.strip.half_extents = Vec2(half_length, 0.5 * depth);
  m.contact_from = a + normal * robot_radius;
  m.contact_to = b + normal * robot_radius;
  m.push = -normal;
  return m;
}

// Sector k of a cylinder of radius `radius`: the robot touching it anywhere on that arc pushes it towards
// its axis (the contact normal passes through it), so the push runs through the middle of the arc and a
// touch off it slides the body sideways as the physics says.
MRegionTemplate cylinder_sector(int sector, double radius, double depth, double robot_radius) {
  const double half_angle = std::numbers::pi / scenario::kCylinderSectors;
  const double angle = 2.0 * half_angle * sector;
  const Vec2 normal(std::cos(angle), std::sin(angle));
  MRegionTemplate m;
  m.face = sector;
  m.strip.pose = {normal * (radius + 0.5 * depth), angle};
  m.strip.half_extents = Vec2(0.5 * depth, (radius + depth) * std::tan(half_angle));
  const double touching = radius + robot_radius;
  m.contact_from = touching * Vec2(std::cos(angle - half_angle), std::sin(angle - half_angle));
  m.contact_to = touching * Vec2(std::cos(angle + half_angle), std::sin(angle + half_angle));
  m.push = -normal;
  return m;
}

namespace box {

std::optional<MRegionTemplate> face(const geometry::Shape& shape, int face, double depth, double robot_radius) {
  return box_side(static_cast<scenario::Side>(face), shape.half_extents(), depth, robot_radius);
}

double distance(const Obstacle& o, const Vec2& p) {
  const Vec2 outside = (o.local(p - o.center()).cwiseAbs() - o.shape().half_extents()).cwiseMax(0.0);
  return outside.norm();
}

// The grown box is the union of two crossed rectangles and four corner discs; the line meets that convex
// union in one interval, the hull of the pieces' intervals.
void closer_than(const Obstacle& obstacle, const Vec2& origin, const Vec2& direction, double radius, std::vector<Interval>& out) {
  const Vec2 o = obstacle.local(origin - obstacle.center());
  const Vec2 u = obstacle.local(direction);
  const Vec2& h = obstacle.shape().half_extents();
  Hull hull;
  hull.include(inside_rectangle(o, u, {h.x() + radius, h.y()}));
  hull.include(inside_rectangle(o, u, {h.x(), h.y() + radius}));
  for (const Vec2& corner : {Vec2(h.x(), h.y()), Vec2(-h.x(), h.y()), Vec2(h.x(), -h.y()), Vec2(-h.x(), -h.y())}) {
    hull.include(inside_disc(o, u, corner, radius));
  }
  keep(hull.interval, out);
}

constexpr ShapeKindKnowledge kRow{face, distance, closer_than};

}  // namespace box

namespace cylinder {

constexpr ShapeKindKnowledge kRow{
    [](const geometry::Shape& shape, int face, double depth, double robot_radius) -> std::optional<MRegionTemplate> {
      return cylinder_sector(face, shape.radius(), depth, robot_radius);
    },
    [](const Obstacle& o, const Vec2& p) { return geometry::distance(o.shape(), o.pose(), p); },
    [](const Obstacle& o, const Vec2& origin, const Vec2& direction, double radius, std::vector<Interval>& out) {
      keep(inside_disc(origin, direction, o.center(), o.shape().radius() + radius), out);
    },
};

}  // namespace cylinder

namespace polygon {

void closer_than(const Obstacle& obstacle, const Vec2& origin, const Vec2& direction, double radius, std::vector<Interval>& out);

// The longest stretch of [0, length] that no interval of `blocked` covers, as [lo, hi].
Interval longest_free(std::vector<Interval>& blocked, double length) {
  std::sort(blocked.begin(), blocked.end(), [](const Interval& a, const Interval& b) { return a.lo < b.lo; });
  Interval best{0.0, 0.0};
  double t = 0.0;
  for (const Interval& b : blocked) {
    if (t >= length) break;
    const double end = std::min(b.lo, length);  // intervals may run past the face
    if (end - t > best.hi - best.lo) best = {t, end};
    t = std::max(t, b.hi);
  }
  if (length - t > best.hi - best.lo) best = {t, length};
  return best;
}

// Face k from corner k to corner k + 1. On a concave outline, only the stretch of it the robot can touch
// without overlapping the body's other parts (a notch's sides and bottom are out of its reach when the
// notch is narrower than the robot): the longest such stretch, nothing when none is kMinFreeStretch long.
std::optional<MRegionTemplate> face(const geometry::Shape& shape, int face, double depth, double robot_radius) {
  const auto& v = shape.outline().vertices;
  const Vec2 a = v[static_cast<size_t>(face)], b = v[(static_cast<size_t>(face) + 1) % v.size()];
  const Vec2 edge = (b - a).normalized();
  // The outside of a counter-clockwise outline is on the right of each side, of a clockwise one on the left.
  const double turn = shape.outline().signed_area() > 0 ? 1.0 : -1.0;
  const Vec2 normal = turn * Vec2(edge.y(), -edge.x());
  if (shape.parts().size() <= 1) return straight_face(face, a, b, normal, depth, robot_radius);
  // The robot touching the face stands at its radius from it: a hair less counts only the other parts.
  constexpr double kTouching = 1e-6;  // m
  std::vector<Interval> blocked;
  closer_than(Obstacle(shape, {}), a + robot_radius * normal, edge, robot_radius - kTouching, blocked);
  const Interval free = longest_free(blocked, (b - a).norm());
  if (free.hi - free.lo < kMinFreeStretch) return std::nullopt;
  return straight_face(face, a + free.lo * edge, a + free.hi * edge, normal, depth, robot_radius);
}

// The convex polygon grown by a disc is the polygon, a rectangle outside each side and a disc at each
// corner; the line meets that convex union in one interval, the hull of the pieces' intervals.
Interval grown_convex(const Vec2& origin, const Vec2& direction, const geometry::Polygon& part, double radius) {
  Hull hull;
  const auto& v = part.vertices;
  hull.include(inside_convex(origin, direction, v));
  for (size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
    const Vec2 edge = v[i] - v[j];
    const double length = edge.norm();
    if (length == 0.0) continue;
    const Vec2 out = radius * Vec2(edge.y(), -edge.x()) / length;
    hull.include(inside_convex(origin, direction, {v[j], v[j] + out, v[i] + out, v[i]}));
    hull.include(inside_disc(origin, direction, v[i], radius));
  }
  return hull.interval;
}

// In the body's frame, where the parts are kept: one interval per part.
void closer_than(const Obstacle& obstacle, const Vec2& origin, const Vec2& direction, double radius, std::vector<Interval>& out) {
  const Vec2 o = obstacle.local(origin - obstacle.center()), u = obstacle.local(direction);
  for (const geometry::Polygon& part : obstacle.shape().parts()) keep(grown_convex(o, u, part, radius), out);
}

constexpr ShapeKindKnowledge kRow{face, [](const Obstacle& o, const Vec2& p) { return geometry::distance(o.shape(), o.pose(), p); },
                                  closer_than};

}  // namespace polygon

// geometry::Shape::Kind order.
constexpr std::array<const ShapeKindKnowledge*, 3> kKinds = {&box::kRow, &cylinder::kRow, &polygon::kRow};

}  // namespace

const ShapeKindKnowledge& kind_of(const geometry::Shape& shape) { return *kKinds[static_cast<std::size_t>(shape.kind())]; }

}  // namespace physltl::knowledge
