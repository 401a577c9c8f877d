#include "physltl/scenario/world_json.h"

#include "shape_kinds.h"

#include <cmath>
#include <numbers>

namespace physltl::scenario {
namespace {

nlohmann::ordered_json point(const Vec2& p) { return {p.x(), p.y()}; }

nlohmann::ordered_json footprint(const geometry::Footprint& f) { return kind_of(f.shape).to_json(f); }

nlohmann::ordered_json robot_json(const Robot& robot) {
  constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;
  nlohmann::ordered_json j = {{"drive", drive_name(robot.drive)},
                              {"radius", robot.radius},
                              {"mass", robot.mass},
                              {"max_force", robot.max_force},
                              {"max_speed", robot.max_speed},
                              {"friction", robot.friction},
                              {"start", point(robot.start)}};
  if (robot.drive == Drive::kDifferential) {
    j["max_turn_rate_deg"] = robot.max_turn_rate * kDegreesPerRadian;
    j["start_yaw_deg"] = robot.start_yaw * kDegreesPerRadian;
  }
  return j;
}

}  // namespace

nlohmann::ordered_json to_json(const World& world) {
  using json = nlohmann::ordered_json;
  json bodies = json::array();
  for (const auto& b : world.fixed_bodies) {
    json j = footprint(b.footprint);
    j["name"] = b.name;
    j["kind"] = "fixed";
    j["height"] = b.height;
    if (!b.mesh.empty()) j["mesh"] = b.mesh, j["scale"] = b.mesh_scale;
    j["defined_at"] = b.where.str();
    bodies.push_back(std::move(j));
  }
  for (const auto& b : world.movable_bodies) {
    json j = footprint(b.footprint);
    j["name"] = b.name;
    j["kind"] = "movable";
    j["height"] = b.height;
    j["mass"] = b.mass;
    j["friction"] = b.friction;
    json sides = json::array();
    for (int face : b.push_from) sides.push_back(face_name(b.footprint.shape, face));
    j["push_from"] = sides;
    j["mregion_depth"] = b.mregion_depth ? json(*b.mregion_depth) : json(nullptr);
    j["defined_at"] = b.where.str();
    bodies.push_back(std::move(j));
  }
  json regions = json::array();
  for (const auto& r : world.regions) {
    json polygon = json::array();
    for (const auto& v : r.polygon.vertices) polygon.push_back(point(v));
    regions.push_back({{"name", r.name}, {"polygon", polygon}, {"defined_at", r.where.str()}});
  }
  json groups = json::array();
  for (const auto& g : world.groups) {
    groups.push_back({{"name", g.name}, {g.bodies.empty() ? "regions" : "bodies", g.bodies.empty() ? g.regions : g.bodies},
                      {"defined_at", g.where.str()}});
  }
  const auto& p = world.planner;
  const auto& rs = world.render;
  return {
      {"scenario", world.source_file},
      {"name", world.name},
      {"workspace",
       {{"min", point(world.workspace.bounds.min)},
        {"max", point(world.workspace.bounds.max)},
        {"floor_friction", world.workspace.floor_friction}}},
      {"robot", robot_json(world.robot)},
      {"bodies", bodies},
      {"regions", regions},
      {"groups", groups},
      {"formula", world.task.formula},
      {"planner",
       {{"time_limit", p.time_limit},
        {"step_size", p.step_size},
        {"min_steps", p.min_steps},
        {"max_steps", p.max_steps},
        {"seed", p.seed},
        {"cost", p.cost.text()},
        {"improve_margin", p.improve_margin},
        {"max_overlap", p.max_overlap}}},
      {"render",
       {{"width", rs.width},
        {"height", rs.height},
        {"fps", rs.fps},
        {"view", render_view_name(rs.view)},
        {"camera",
         {{"target", rs.camera.target ? point(*rs.camera.target) : nlohmann::ordered_json(nullptr)},
          {"distance", rs.camera.distance},
          {"elevation_deg", rs.camera.elevation_deg},
          {"azimuth_deg", rs.camera.azimuth_deg ? nlohmann::ordered_json(*rs.camera.azimuth_deg) : nlohmann::ordered_json(nullptr)},
          {"fov_deg", rs.camera.fov_deg}}}}},
  };
}

}  // namespace physltl::scenario
