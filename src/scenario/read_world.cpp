#include "read_world.h"

#include "physltl/ltl/parser.h"

#include "read_expectations.h"
#include "shape_kinds.h"
#include "table_reader.h"

#include "physltl/geometry/convex_partition.h"
#include "physltl/geometry/mesh.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <optional>

namespace physltl::scenario {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// Far beyond any world the planner can take, and small enough that validation's pairwise overlap checks
// stay well under a second: a script looping over constructors must not turn loading into a hang.
constexpr std::size_t kMaxRegionCorners = 10'000;  // all regions together

bool is_singleton(const std::string& kind) {
  return kind != "fixed" && kind != "movable" && kind != "region" && kind != "group";
}

bool written_in(const Element& e, const std::string& path) {
  std::error_code ec;
  return std::filesystem::equivalent(e.where.file, path, ec);
}

std::string element_label(const Element& e, int index_of_kind) {
  if (is_singleton(e.kind)) return e.kind;
  const LuaValue* name = e.table.field("name");
  if (name && name->kind == LuaValue::Kind::kString) return e.kind + " '" + name->string + "'";
  return e.kind + " #" + std::to_string(index_of_kind);
}

// Far beyond a body anyone draws by hand, and within what a movable body's faces can number (kappa keeps
// them in 32 bits).
constexpr std::size_t kMaxFixedPolygonCorners = 1000;
constexpr std::size_t kMaxMovablePolygonCorners = 32;
constexpr std::size_t kMaxParts = 64;

geometry::Pose2 read_pose(TableReader& r) { return {r.point("center"), r.number("yaw_deg", 0.0) * kDegree}; }

// A compound body's `parts`: convex polygons that overlap or touch along edges into one piece without
// holes; the outline of their union (faces are numbered along it, counter-clockwise), or nothing with the
// error said.
std::optional<geometry::Polygon> read_parts_outline(TableReader& r, std::size_t corner_limit) {
  const std::vector<std::vector<Vec2>> lists = r.point_lists("parts");
  if (lists.empty() || lists.size() > kMaxParts) {
    r.error("'parts' lists 1 to " + std::to_string(kMaxParts) + " convex polygons {{x, y}, ...}");
    return std::nullopt;
  }
  std::vector<geometry::Polygon> parts;
  for (std::size_t i = 0; i < lists.size(); ++i) {
    const geometry::Polygon part{lists[i]};
    if (part.vertices.size() < 3 || part.vertices.size() > corner_limit || !part.is_simple() || !geometry::is_convex(part)) {
      r.error("part " + std::to_string(i + 1) + " of 'parts' must be a convex polygon of 3 to " + std::to_string(corner_limit) +
              " corners with a positive area");
      return std::nullopt;
    }
    parts.push_back(part);
  }
  std::optional<geometry::Polygon> outline = geometry::union_outline(parts);
  if (!outline) {
    r.error("'parts' must join into one piece without holes (each part overlapping or sharing an edge with another, "
            "not meeting at a corner only)");
  } else if (outline->vertices.size() > corner_limit) {
    r.error("the outline of 'parts' has " + std::to_string(outline->vertices.size()) + " corners, more than the " +
            std::to_string(corner_limit) + " a body of this kind may have");
    return std::nullopt;
  }
  return outline;
}

// A polygon given as `polygon` (world frame), as `points` about `center` turned by `yaw_deg`, or as the
// union of convex `parts` about `center` (a compound body): its pose is its area centroid with that
// heading, its outline the corners about it, cut into convex parts for the physics and every query. A
// movable body is one rigid body whatever its outline.
geometry::Footprint read_polygon(TableReader& r, bool movable) {
  const int forms = int{r.has("polygon")} + int{r.has("points")} + int{r.has("parts")};
  if (forms != 1) {
    r.error("a polygon takes exactly one of 'polygon' = {{x, y}, ...} (world frame), 'points' = {{x, y}, ...} "
            "about 'center', or 'parts' = {{{x, y}, ...}, ...} (convex pieces about 'center')");
    r.skip_unread();
    return {};
  }
  const bool in_world = r.has("polygon");
  geometry::Pose2 placed;
  if (!in_world) placed = read_pose(r);
  const std::size_t limit = movable ? kMaxMovablePolygonCorners : kMaxFixedPolygonCorners;
  std::vector<Vec2> corners;
  if (r.has("parts")) {
    std::optional<geometry::Polygon> outline = read_parts_outline(r, limit);
    if (!outline) return {};
    corners = outline->vertices;
  } else {
    corners = r.points(in_world ? "polygon" : "points");
  }
  const geometry::Polygon authored{corners};
  if (corners.size() < 3 || corners.size() > limit || !authored.is_simple()) {
    r.error("a polygon needs 3 to " + std::to_string(limit) + " corners, a positive area and no crossing edges");
    return {};
  }
  // The centre the pose names, and the object propositions test, is the area centroid.
  const Vec2 centroid = authored.centroid();
  geometry::Polygon outline;
  for (const Vec2& c : corners) outline.vertices.push_back(c - centroid);
  geometry::Pose2 pose{geometry::to_world(placed, centroid), placed.yaw};
  if (in_world) pose = {centroid, 0.0};
  std::vector<geometry::Polygon> parts = geometry::convex_partition(outline);
  return {pose, geometry::Shape::polygon(std::move(outline), std::move(parts))};
}

// The body's outline and pose from its `shape` and that shape's keys (docs/scenarios.md, "Shapes").
geometry::Footprint read_footprint(TableReader& r, bool movable) {
  const std::string shape = r.string("shape", "box");
  if (shape == "box") {
    const geometry::Pose2 pose = read_pose(r);
    return {pose, geometry::Shape::box(0.5 * r.point("size"))};
  }
  if (shape == "cylinder") {
    // A cylinder has no heading to give: it looks and collides the same however it is turned.
    return {{r.point("center"), 0.0}, geometry::Shape::circle(r.number("radius"))};
  }
  if (shape == "polygon") return read_polygon(r, movable);
  r.error("'shape' is \"box\", \"cylinder\" or \"polygon\", got \"" + shape + "\"");
  r.skip_unread();
  return {};
}

void read_workspace(TableReader& r, Workspace& w) {
  const auto corners = r.points("bounds");
  if (corners.size() == 2) {
    w.bounds = {corners[0], corners[1]};
  } else {
    r.error("'bounds' must be two corners {{min_x, min_y}, {max_x, max_y}}");
  }
  w.floor_friction = r.number("floor_friction", w.floor_friction);
}

void read_robot(TableReader& r, Robot& robot) {
  const std::string drive = r.string("drive", drive_name(robot.drive));
  if (drive == drive_name(Drive::kDifferential)) {
    robot.drive = Drive::kDifferential;
    robot.max_turn_rate = r.number("max_turn_rate_deg", robot.max_turn_rate / kDegree) * kDegree;
    robot.start_yaw = r.number("start_yaw_deg", 0.0) * kDegree;
  } else if (drive != drive_name(Drive::kHolonomic)) {
    r.error("'drive' is \"holonomic\" or \"differential\", got \"" + drive + "\"");
  } else {
    for (const char* key : {"max_turn_rate_deg", "start_yaw_deg"}) {
      if (r.optional_number(key)) r.error(std::string("'") + key + "' is for drive = \"differential\": a holonomic robot never turns");
    }
  }
  robot.radius = r.number("radius", robot.radius);
  robot.mass = r.number("mass", robot.mass);
  robot.max_force = r.number("max_force", robot.max_force);
  robot.max_speed = r.number("max_speed", robot.max_speed);
  robot.friction = r.number("friction", robot.friction);
  robot.start = r.point("start");
}

FixedBody read_fixed(TableReader& r, const std::string& default_name, const std::string& script_dir) {
  FixedBody body;
  body.name = r.string("name", default_name);
  body.mesh = r.string("mesh", "");
  if (body.mesh.empty() && r.has("mesh")) {
    r.error("'mesh' must name an OBJ file, got an empty string");
    r.skip_unread();
    return body;
  }
  if (body.mesh.empty()) {
    body.footprint = read_footprint(r, false);
  } else {
    // A mesh collides as it is drawn: its footprint is found once the robot's size is known (read_world).
    if (r.has("size") || r.has("shape")) {
      r.error("a mesh collides as its own footprint: give 'mesh' with 'center', 'yaw_deg' and 'scale', not 'size' or "
              "'shape'");
      r.skip_unread();
    }
    body.footprint.pose = read_pose(r);
    body.mesh_scale = r.number("scale", 1.0);
    if (std::filesystem::path(body.mesh).is_relative()) {
      body.mesh = (std::filesystem::path(script_dir) / body.mesh).lexically_normal().string();
    }
  }
  if (const auto height = r.optional_number("height")) {
    body.height = *height;
  } else if (!body.mesh.empty()) {
    body.height = 0.0;  // the mesh's own, once it is read
  }
  return body;
}

MovableBody read_movable(TableReader& r, const std::string& default_name) {
  MovableBody body;
  body.name = r.string("name", default_name);
  body.footprint = read_footprint(r, true);
  body.height = r.number("height", body.height);
  body.mass = r.number("mass", body.mass);
  body.friction = r.number("friction", body.friction);
  const geometry::Shape& shape = body.footprint.shape;
  if (r.has("push_from")) body.push_from = kind_of(shape).read_push_from(r, shape);
  body.mregion_depth = r.optional_number("mregion_depth");
  if (auto u = r.nested("uncertainty")) {
    body.uncertainty = {u->optional_number("mass"), u->optional_number("friction"), u->optional_number("pose"),
                        u->optional_number("yaw_deg")};
    u->finish();
  }
  return body;
}

Region read_region(TableReader& r) {
  Region region;
  region.name = r.string("name");
  const bool has_rect = r.has("rect"), has_polygon = r.has("polygon");
  if (has_rect == has_polygon) {
    r.error("give exactly one of 'rect' = {{min_x, min_y}, {max_x, max_y}} or 'polygon' = {{x, y}, ...}");
  }
  if (has_rect) {
    const auto corners = r.points("rect");
    if (corners.size() == 2 && (corners[1].array() <= corners[0].array()).any()) {
      r.error("'rect' must go from the smaller corner to the larger one, {{min_x, min_y}, {max_x, max_y}}");
    } else if (corners.size() == 2) {
      region.polygon = geometry::Polygon::from_rect({corners[0], corners[1]});
    } else {
      r.error("'rect' must be two corners {{min_x, min_y}, {max_x, max_y}}");
    }
  }
  if (has_polygon) region.polygon.vertices = r.points("polygon");
  return region;
}

// Its members' names; validation checks them against the World once every element is read.
Group read_group(TableReader& r) {
  Group group;
  group.name = r.string("name");
  const bool has_bodies = r.has("bodies"), has_regions = r.has("regions");
  if (has_bodies == has_regions) {
    r.error("give exactly one of 'bodies' = {\"M1\", ...} or 'regions' = {\"goal1\", ...}");
    r.skip_unread();
    return group;
  }
  (has_bodies ? group.bodies : group.regions) = r.strings(has_bodies ? "bodies" : "regions");
  if (group.bodies.empty() && group.regions.empty()) r.error(std::string("'") + (has_bodies ? "bodies" : "regions") + "' is empty");
  return group;
}

void read_planner(TableReader& r, PlannerSettings& p) {
  p.time_limit = r.number("time_limit", p.time_limit);
  p.step_size = r.number("step_size", p.step_size);
  p.min_steps = r.integer("min_steps", p.min_steps);
  p.max_steps = r.integer("max_steps", p.max_steps);
  p.improve_margin = r.number("improve_margin", p.improve_margin);
  p.max_overlap = r.number("max_overlap", p.max_overlap);
  if (r.has("cost")) {
    try {
      p.cost = parse_plan_cost(r.string("cost"));
    } catch (const PlanCostError& e) {
      r.error(std::string("'cost': ") + e.what());
    }
  }
  const double seed = r.number("seed", static_cast<double>(p.seed));
  if (seed < 0 || seed != std::floor(seed) || seed > 9.0e15) {
    r.error("'seed' must be a whole number from 0 to 9e15");
  } else {
    p.seed = static_cast<std::uint64_t>(seed);
  }
}

void read_render(TableReader& r, RenderSettings& s) {
  s.width = r.integer("width", s.width);
  s.height = r.integer("height", s.height);
  s.fps = r.integer("fps", s.fps);
  const std::string view = r.string("view", std::string(render_view_name(s.view)));
  if (const std::optional<RenderView> named = render_view_named(view)) {
    s.view = *named;
  } else {
    r.error("'view' is \"perspective\" or \"top\", got \"" + view + "\"");
  }
  if (auto c = r.nested("camera")) {
    if (c->has("target")) s.camera.target = c->point("target");
    s.camera.distance = c->number("distance", s.camera.distance);
    s.camera.elevation_deg = c->number("elevation_deg", s.camera.elevation_deg);
    if (const auto azimuth = c->optional_number("azimuth_deg")) s.camera.azimuth_deg = *azimuth;
    s.camera.fov_deg = c->number("fov_deg", s.camera.fov_deg);
    c->finish();
  }
}

void read_uncertainty(TableReader& r, Uncertainty& u) {
  u.mass = r.number("mass", u.mass);
  u.friction = r.number("friction", u.friction);
  u.start = r.number("start", u.start);
  u.body_pose = r.number("body_pose", u.body_pose);
  u.body_yaw_deg = r.number("body_yaw_deg", u.body_yaw_deg);
}

// The formula is parsed here, once: every layer above takes Task::parsed.
void read_task(TableReader& r, Task& task) {
  task.formula = r.string("formula");
  try {
    task.parsed = ltl::parse(task.formula);
  } catch (const ltl::ParseError& e) {
    r.error("formula '" + task.formula + "': " + e.what());
  }
}

// Each mesh's footprint: the floor projection of what stands below the robot's top, so the robot never
// passes under anything it would hit; its height, unless given, the mesh's own.
void place_meshes(World& world, std::vector<Diagnostic>& diagnostics) {
  const double robot_top = 2.0 * world.robot.radius;
  for (FixedBody& body : world.fixed_bodies) {
    if (body.mesh.empty()) continue;
    const std::string what = "fixed '" + body.name + "': ";
    if (!(body.mesh_scale > 0.0) || body.mesh_scale > 1e3) {
      diagnostics.push_back({body.where, what + "'scale' must be greater than 0 and at most 1000"});
      continue;
    }
    try {
      const geometry::Mesh mesh = geometry::read_obj(body.mesh);
      std::vector<geometry::Polygon> parts = geometry::floor_footprint(mesh, body.mesh_scale, robot_top);
      if (parts.empty()) {
        diagnostics.push_back({body.where, what + "mesh '" + body.mesh + "' has nothing at or below the robot's top (" +
                                               std::to_string(robot_top) + " m) to collide with"});
        continue;
      }
      body.footprint.shape = geometry::Shape::polygon({}, std::move(parts));
      if (body.height == 0.0) {
        for (const auto& triangle : mesh.triangles) {
          for (const auto& corner : triangle) body.height = std::max(body.height, body.mesh_scale * corner.z());
        }
      }
    } catch (const geometry::MeshError& e) {
      diagnostics.push_back({body.where, what + e.what()});
    }
  }
}

// One element of the script into `world`, by its kind; `index` counts the elements of that kind so far.
void read_element(TableReader& r, const Element& e, int index, const std::string& script_dir, World& world,
                  std::size_t& region_corners) {
  if (e.kind == "workspace") {
    read_workspace(r, world.workspace);
    world.workspace.where = e.where;
  } else if (e.kind == "robot") {
    read_robot(r, world.robot);
    world.robot.where = e.where;
  } else if (e.kind == "fixed") {
    world.fixed_bodies.push_back(read_fixed(r, "fixed_" + std::to_string(index), script_dir));
    world.fixed_bodies.back().where = e.where;
  } else if (e.kind == "movable") {
    world.movable_bodies.push_back(read_movable(r, "movable_" + std::to_string(index)));
    world.movable_bodies.back().where = e.where;
  } else if (e.kind == "region") {
    world.regions.push_back(read_region(r));
    world.regions.back().where = e.where;
    region_corners += world.regions.back().polygon.vertices.size();
    if (region_corners > kMaxRegionCorners) {
      r.error("the regions have more than " + std::to_string(kMaxRegionCorners) + " corners together");
    }
  } else if (e.kind == "group") {
    world.groups.push_back(read_group(r));
    world.groups.back().where = e.where;
  } else if (e.kind == "task") {
    read_task(r, world.task);
    world.task.where = e.where;
  } else if (e.kind == "planner") {
    read_planner(r, world.planner);
    world.planner.where = e.where;
  } else if (e.kind == "render") {
    read_render(r, world.render);
    world.render.where = e.where;
  } else if (e.kind == "uncertainty") {
    read_uncertainty(r, world.uncertainty);
    world.uncertainty.where = e.where;
  } else if (e.kind == "expect") {
    world.expect = read_expectations(r);
    world.expect->where = e.where;
  }
}

}  // namespace

World read_world(const std::vector<Element>& elements, const std::string& path, std::vector<Diagnostic>& diagnostics) {
  World world;
  world.source_file = path;
  world.name = std::filesystem::path(path).stem().string();
  const std::string script_dir = std::filesystem::path(path).parent_path().string();

  // Singletons: exactly once (workspace, robot, task) or at most once (planner, render, uncertainty, expect).
  std::map<std::string, const Element*> first_of;
  std::map<std::string, int> count_of;
  std::size_t region_corners = 0;
  for (const Element& e : elements) {
    if (e.kind == "expect" && !written_in(e, path)) {
      // A scenario required as a module keeps its own expectations for its own test; checked all the same.
      TableReader r(e.table, "expect (of " + e.where.file + ")", e.where, diagnostics);
      read_expectations(r);
      r.finish();
      continue;
    }
    const int index = ++count_of[e.kind];
    if (is_singleton(e.kind) && index > 1) {
      diagnostics.push_back({e.where, e.kind + " is given twice (first at " + first_of[e.kind]->where.str() + ")"});
      continue;
    }
    if ((e.kind == "fixed" || e.kind == "movable") && index > max_bodies_of_kind(e.kind)) {
      if (index == max_bodies_of_kind(e.kind) + 1) {
        diagnostics.push_back({e.where, "more than " + std::to_string(max_bodies_of_kind(e.kind)) + " " + e.kind + " bodies"});
      }
      continue;
    }
    if (e.kind == "region" && region_corners > kMaxRegionCorners) continue;  // reported once, at the first too many
    first_of.emplace(e.kind, &e);
    TableReader r(e.table, element_label(e, index), e.where, diagnostics);
    read_element(r, e, index, script_dir, world, region_corners);
    r.finish();
  }
  place_meshes(world, diagnostics);
  check_expectations(world, diagnostics);
  for (const char* required : {"workspace", "robot", "task"}) {
    if (!count_of.count(required)) {
      diagnostics.push_back({{path, 1}, std::string("the scenario has no ") + required + " { ... }"});
    }
  }
  // Elements that were not given point at the top of the file, where an author would add them.
  for (Location* where : {&world.planner.where, &world.render.where, &world.uncertainty.where}) {
    if (where->file.empty()) *where = {path, 1};
  }
  return world;
}

}  // namespace physltl::scenario
