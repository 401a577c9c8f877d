#include "physltl/knowledge/report.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace physltl::knowledge {
namespace {

using json = nlohmann::ordered_json;

json point(const geometry::Vec2& p) { return {p.x(), p.y()}; }

// A box's strips lie along its own axes, as they always did; other shapes' strips are turned too.
json mregion_json(const MovableBodyKnowledge& body, const MRegionTemplate& m) {
  json j = {{"side", scenario::face_name(body.footprint.shape, m.face)},
            {"center", point(m.strip.pose.position)},
            {"size", point(2.0 * m.strip.half_extents)}};
  if (!body.footprint.shape.is_box()) j["yaw_deg"] = m.strip.pose.yaw * 180.0 / std::numbers::pi;
  return j;
}

json movable_report(const MovableBodyKnowledge& body, const BodyKappa& kappa, const geometry::Pose2& pose) {
  json active = json::array(), inactive = json::array(), directions = json::array();
  for (const MRegionTemplate& m : body.mregions) {
    (kappa.active_faces.contains(m.face) ? active : inactive).push_back(scenario::face_name(body.footprint.shape, m.face));
  }
  for (const geometry::Vec2& d : allowed_push_directions(body, kappa, pose)) directions.push_back(direction_name(d));
  return {{"name", body.name},
          {"class", class_name(body.body_class)},
          {"class_reason", body.class_reason},
          {"type", type_name(kappa.type)},
          {"active_mregions", active},
          {"inactive_mregions", inactive},
          {"allowed_push_directions", directions}};
}

}  // namespace

std::string direction_name(const geometry::Vec2& d) {
  constexpr double kAligned = 0.99996;  // cos(0.5 deg)
  if (d.x() > kAligned) return "+x";
  if (d.x() < -kAligned) return "-x";
  if (d.y() > kAligned) return "+y";
  if (d.y() < -kAligned) return "-y";
  return fmt::format("[{:.2f}, {:.2f}]", d.x(), d.y());
}

json to_json(const AbstractKnowledge& k) {
  json bodies = json::array();
  for (const auto& f : k.fixed_bodies) {
    bodies.push_back({{"name", f.name}, {"class", class_name(BodyClass::kFixed)}});
  }
  for (const auto& m : k.movable_bodies) {
    json mregions = json::array();
    for (const auto& t : m.mregions) mregions.push_back(mregion_json(m, t));
    const geometry::Shape& shape = m.footprint.shape;
    bodies.push_back({{"name", m.name},
                      {"class", class_name(m.body_class)},
                      {"class_reason", m.class_reason},
                      {"size", point(geometry::bounds(shape, {}).max - geometry::bounds(shape, {}).min)},
                      {"mass", m.mass},
                      {"friction", m.friction},
                      {"floor_friction_force", m.floor_friction_force},
                      {"mregions", mregions}});
  }
  json propositions = json::array();
  for (const auto& p : k.propositions) propositions.push_back(p.name);
  const RobotCapabilities& r = k.robot;
  return {{"workspace", {{"min", point(k.workspace.min)}, {"max", point(k.workspace.max)}}},
          {"robot",
           {{"radius", r.radius},
            {"mass", r.mass},
            {"drive", scenario::drive_name(r.drive)},
            {"max_force", r.max_force},
            {"max_speed", r.max_speed},
            {"max_turn_rate_deg", r.max_turn_rate * 180.0 / std::numbers::pi},
            {"push_force", r.push_force},
            {"start", point(r.start)}}},
          {"bodies", bodies},
          {"propositions", propositions}};
}

json knowledge_report(const AbstractKnowledge& k, const scenario::EnvironmentState& state, const Kappa& kappa,
                      const Feasibility& feasibility) {
  json bodies = json::array();
  for (const auto& f : k.fixed_bodies) {
    bodies.push_back({{"name", f.name}, {"class", class_name(BodyClass::kFixed)}, {"type", "fixed"}});
  }
  for (size_t i = 0; i < k.movable_bodies.size(); ++i) {
    bodies.push_back(movable_report(k.movable_bodies[i], kappa.bodies.at(i), state.movable_poses.at(i)));
  }
  json regions = json::array();
  for (const auto& p : k.propositions) {
    const InvalidProposition* invalid = feasibility.find(p.name);
    regions.push_back({{"name", p.name},
                       {"reachable", invalid == nullptr},
                       {"reason", invalid ? json(invalid->reason) : json(nullptr)}});
  }
  json objects = json::array();
  for (const ObjectVerdict& o : feasibility.objects) {
    objects.push_back({{"name", o.name},
                       {"body", o.body},
                       {"region", o.region},
                       {"reachable", o.reachable},
                       {"always_true", o.always_true},
                       {"reason", o.reason.empty() ? json(nullptr) : json(o.reason)}});
  }
  return {{"bodies", bodies},
          {"regions", regions},
          {"object_propositions", objects},
          {"invalid_propositions", feasibility.invalid_names()},
          {"reachability_cell_size", feasibility.cell_size}};
}

}  // namespace physltl::knowledge
