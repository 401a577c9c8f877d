#include "physltl/knowledge/abstract_knowledge.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace physltl::knowledge {
namespace {

using geometry::Vec2;

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

MRegionTemplate face_template(const geometry::Shape& shape, int face, double depth, double robot_radius) {
  switch (shape.kind()) {
    case geometry::Shape::Kind::kBox:
      return box_side(static_cast<scenario::Side>(face), shape.half_extents(), depth, robot_radius);
    case geometry::Shape::Kind::kCircle: return cylinder_sector(face, shape.radius(), depth, robot_radius);
    case geometry::Shape::Kind::kPolygon: break;
  }
  const auto& v = shape.outline().vertices;
  const Vec2 a = v[static_cast<size_t>(face)], b = v[(static_cast<size_t>(face) + 1) % v.size()];
  const Vec2 edge = (b - a).normalized();
  // The outside of a counter-clockwise outline is on the right of each side, of a clockwise one on the left.
  const double turn = shape.outline().signed_area() > 0 ? 1.0 : -1.0;
  return straight_face(face, a, b, turn * Vec2(edge.y(), -edge.x()), depth, robot_radius);
}

std::string face_list(const geometry::Shape& shape, const std::vector<int>& faces) {
  std::string out;
  for (int f : faces) out += (out.empty() ? "" : ", ") + scenario::face_name(shape, f);
  return out;
}

MovableBodyKnowledge movable_knowledge(const scenario::MovableBody& body, const scenario::World& world,
                                       const RobotCapabilities& robot, const FormulationSettings& settings) {
  MovableBodyKnowledge k;
  k.name = body.name;
  k.footprint = body.footprint;
  k.bound_radius = body.footprint.shape.bound_radius();
  k.faces = scenario::face_count(body.footprint.shape);
  k.mass = body.mass;
  k.friction = body.friction;
  k.floor_friction_force =
      combined_friction(body.friction, world.workspace.floor_friction) * body.mass * settings.gravity;
  if (k.floor_friction_force >= robot.push_force) {
    k.body_class = BodyClass::kFixed;
    k.class_reason = fmt::format(
        "too heavy to push: its floor friction holds it with {:.1f} N, the robot's drive pushes with at "
        "most {:.1f} N",
        k.floor_friction_force, robot.push_force);
    return k;
  }
  FaceSet pushable;
  for (int face : body.push_from) pushable.insert(face);
  if (body.push_from.empty() || pushable == FaceSet::first(k.faces)) {
    pushable = FaceSet::first(k.faces);
    k.body_class = BodyClass::kFreelyMovable;
    k.class_reason = "pushable from every side";
  } else {
    k.body_class = BodyClass::kConstraintOriented;
    k.class_reason = "pushable only from the authored sides " + face_list(body.footprint.shape, body.push_from);
  }
  const double depth = body.mregion_depth.value_or(2.0 * robot.radius + settings.mregion_margin);
  for (int face = 0; face < k.faces; ++face) {
    if (pushable.contains(face)) k.mregions.push_back(face_template(body.footprint.shape, face, depth, robot.radius));
  }
  for (const MRegionTemplate& m : k.mregions) {
    k.contact_reach = std::max({k.contact_reach, m.contact_from.norm(), m.contact_to.norm()});
  }
  return k;
}

}  // namespace

const char* class_name(BodyClass body_class) {
  switch (body_class) {
    case BodyClass::kFixed: return "fixed";
    case BodyClass::kFreelyMovable: return "freely-movable";
    case BodyClass::kConstraintOriented: return "constraint-oriented";
  }
  return "?";
}

double combined_friction(double a, double b) { return std::sqrt(a * b); }

AbstractKnowledge formulate(const scenario::World& world, const FormulationSettings& settings) {
  AbstractKnowledge k;
  k.workspace = world.workspace.bounds;

  const auto& r = world.robot;
  k.robot.radius = r.radius;
  k.robot.mass = r.mass;
  k.robot.drive = r.drive;
  k.robot.max_force = r.max_force;
  k.robot.max_speed = r.max_speed;
  k.robot.max_turn_rate = r.drive == scenario::Drive::kDifferential ? r.max_turn_rate : 0.0;
  k.robot.push_force = r.max_force;
  k.robot.start = r.start;

  for (const auto& f : world.fixed_bodies) {
    k.fixed_bodies.push_back({f.name, f.footprint, geometry::bounds(f.footprint.shape, f.footprint.pose)});
  }
  for (const auto& m : world.movable_bodies) {
    k.movable_bodies.push_back(movable_knowledge(m, world, k.robot, settings));
    k.largest_bound_radius = std::max(k.largest_bound_radius, k.movable_bodies.back().bound_radius);
    k.largest_contact_reach = std::max(k.largest_contact_reach, k.movable_bodies.back().contact_reach);
  }
  for (const auto& region : world.regions) k.propositions.push_back({region.name, region.polygon});

  // A contact segment lies within half its length of its midpoint, and the robot on it within its radius.
  double half_segment = 0.0;
  for (const auto& body : k.movable_bodies) {
    for (const auto& m : body.mregions) half_segment = std::max(half_segment, 0.5 * (m.contact_to - m.contact_from).norm());
  }
  std::vector<geometry::Rect> bounds;
  for (const auto& f : k.fixed_bodies) bounds.push_back(f.bounds);
  k.fixed_near = geometry::RectGrid(bounds, half_segment + k.robot.radius);
  return k;
}

}  // namespace physltl::knowledge
