#include "physltl/knowledge/abstract_knowledge.h"

#include "shape_kinds.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace physltl::knowledge {
namespace {

using geometry::Vec2;

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
  const double depth = body.mregion_depth.value_or(2.0 * robot.radius + settings.mregion_margin);
  std::vector<MRegionTemplate> touchable;
  for (int face = 0; face < k.faces; ++face) {
    if (auto m = kind_of(body.footprint.shape).face_template(body.footprint.shape, face, depth, robot.radius)) {
      touchable.push_back(*m);
      k.touchable_faces.insert(face);
    }
  }
  // Listing every face, or every face the robot can touch, is listing none.
  FaceSet pushable;
  for (int face : body.push_from) pushable.insert(face);
  const bool authored = !body.push_from.empty() && !(pushable == FaceSet::first(k.faces)) && !(pushable == k.touchable_faces);
  for (const MRegionTemplate& m : touchable) {
    if (authored && pushable.contains(m.face)) k.authored_sides.push_back(m);
  }
  if (k.floor_friction_force >= robot.push_force) {
    k.body_class = BodyClass::kFixed;
    k.class_reason = fmt::format(
        "too heavy to push: its floor friction holds it with {:.1f} N, the robot's drive pushes with at "
        "most {:.1f} N",
        k.floor_friction_force, robot.push_force);
    return k;
  }
  if (!authored) {
    k.body_class = BodyClass::kFreelyMovable;
    k.mregions = touchable;
    k.class_reason = static_cast<int>(k.mregions.size()) == k.faces ? "pushable from every side"
                                                                     : "pushable from every side the robot can touch";
  } else {
    k.body_class = BodyClass::kConstraintOriented;
    k.class_reason = "pushable only from the authored sides " + face_list(body.footprint.shape, body.push_from);
    k.mregions = k.authored_sides;
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
