#pragma once
// The World: everything a scenario file describes, in SI units, with the file:line of each element.
// Built by load_scenario(); read-only for every layer above.

#include "physltl/geometry/shape.h"
#include "physltl/geometry/shapes.h"
#include "physltl/scenario/diagnostic.h"
#include "physltl/scenario/expectations.h"
#include "physltl/scenario/plan_cost.h"
#include "physltl/ltl/formula.h"

#include <cstdint>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <string_view>
#include <vector>

namespace physltl::scenario {

using geometry::Vec2;

struct Workspace {
  geometry::Rect bounds;
  double floor_friction = 0.5;
  Location where{};
};

// How the robot moves. Both drives track a velocity set-point with a force bounded by max_force
// (docs/physics.md): holonomic in any direction without turning; differential only along its heading,
// turning in place or on the move, its wheels gripping the floor sideways.
enum class Drive { kHolonomic, kDifferential };
const char* drive_name(Drive drive);  // "holonomic", "differential"

// The paper's mobile robot: a disc on the floor (drawn as a sphere) with a velocity-tracking drive.
struct Robot {
  Drive drive = Drive::kHolonomic;
  double radius = 0.25;     // m
  double mass = 1.0;        // kg
  double max_force = 20.0;  // N: Euclidean norm of the drive force (holonomic), forward traction (differential)
  double max_speed = 1.0;   // m/s, never exceeded at any physics step
  double max_turn_rate = 0.5 * std::numbers::pi;  // rad/s, differential only
  double friction = 0.5;
  Vec2 start = Vec2::Zero();
  double start_yaw = 0.0;  // rad, differential only
  Location where{};
};

// One side of a box in its own frame: the robot stands on this side to push towards the opposite one.
enum class Side { kMinusX, kPlusX, kMinusY, kPlusY };
const char* side_name(Side side);  // "-x", "+x", "-y", "+y"

// The faces the robot can push a body from, numbered 0, 1, ...: a box's four sides (as Side), a polygon's
// sides (face k from corner k to corner k + 1 of its outline), and a cylinder's sectors, kCylinderSectors
// equal arcs (sector k about the direction 2 pi k / kCylinderSectors of its frame).
inline constexpr int kCylinderSectors = 12;
int face_count(const geometry::Shape& shape);
// "-x" for a box, "face 2" for a polygon (1-based, as scenarios write them), "sector 3" for a cylinder.
std::string face_name(const geometry::Shape& shape, int face);
// "box", "cylinder", "polygon".
const char* shape_name(const geometry::Shape& shape);
// Its size in words: "0.5 x 0.5 m", "cylinder r = 0.3 m", "polygon of 5 corners, 0.42 m2".
std::string shape_size_text(const geometry::Shape& shape);

struct FixedBody {
  std::string name;
  // Pose and outline; a mesh's outline is its floor footprint below the robot's top (geometry/mesh.h).
  geometry::Footprint footprint;
  double height = 0.5;
  std::string mesh;  // optional OBJ file: drawn, and its footprint collides
  double mesh_scale = 1.0;
  Location where{};
};

// A movable body's own ranges (movable { uncertainty = { ... } }), each replacing the world's for it.
struct BodyUncertainty {
  std::optional<double> mass, friction;  // relative
  std::optional<double> pose;            // m
  std::optional<double> yaw_deg;
};

struct MovableBody {
  std::string name;
  geometry::Footprint footprint;  // pose: the centre (a polygon's area centroid) and the heading
  double height = 0.5;
  double mass = 0.5;
  double friction = 0.5;
  // Authored manipulation constraints, as faces (face_count); empty means every face (the knowledge
  // layer decides).
  std::vector<int> push_from;
  std::optional<double> mregion_depth;  // m; default derived from the robot's size
  BodyUncertainty uncertainty;
  Location where{};
};

struct Region {
  std::string name;  // the proposition, used in the formula
  geometry::Polygon polygon;
  Location where{};
};

// Several movable bodies, or several regions, under one name, so that one object proposition speaks of
// them all: GROUP@REGIONS holds when every body of the group has its centre in some region of the set
// ("every box on some goal", docs/scenarios.md#groups). Exactly one of the two lists is given.
struct Group {
  std::string name;
  std::vector<std::string> bodies;   // movable bodies' names
  std::vector<std::string> regions;  // regions' names
  Location where{};
};

struct Task {
  std::string formula;  // as written
  // The formula, parsed once as the scenario is read: everything downstream takes it from here.
  ltl::Formula parsed = ltl::Formula::tt();
  Location where{};
};

// Seconds of planning when a scenario does not say.
inline constexpr double kDefaultTimeLimit = 60.0;

struct PlannerSettings {
  double time_limit = kDefaultTimeLimit;  // s of planning
  double step_size = 0.05;   // s per physics step
  int min_steps = 2;         // physics steps per control
  int max_steps = 30;
  std::uint64_t seed = 1;
  PlanCost cost;  // what improvement lowers: the motion's time unless the scenario or --cost says
  // Metres improvement keeps from the fixed bodies and inside the regions the robot visits for its task,
  // where the plan it improves did (docs/planner.md, "A margin for the real world"); 0: none.
  double improve_margin = 0.0;
  // The deepest any body may sink into another (m), at any physics step: a step deeper is invalid, in the
  // search and in the replay (docs/physics.md, "No body sinks into another"). At most kMaxOverlapLimit.
  double max_overlap = 0.01;
  Location where{};
};
inline constexpr double kMaxOverlapLimit = 0.02;  // m

struct Camera {
  std::optional<Vec2> target;  // unset: the workspace's centre, and the picture centred on the workspace
  double distance = 0.0;       // 0: fit the workspace
  double elevation_deg = 55.0;
  // Unset: from the south (-90) or the east (0), whichever shows the workspace larger, so that a tall world
  // runs across a wide frame (docs/rendering.md, "Framing").
  std::optional<double> azimuth_deg;
  double fov_deg = 45.0;
};

// How the frames of a plan (and preview.png) look at the world: the camera's 3/4 view, or straight down.
enum class RenderView { kPerspective, kTop };
inline constexpr RenderView kRenderViews[] = {RenderView::kPerspective, RenderView::kTop};
std::string_view render_view_name(RenderView view);
// The view named `name` ("perspective" or "top"), or none for another name.
std::optional<RenderView> render_view_named(std::string_view name);

struct RenderSettings {
  int width = 640;
  int height = 480;
  int fps = 30;
  RenderView view = RenderView::kPerspective;
  Camera camera;
  Location where{};
};

// How far reality may differ from the model (docs/robustness.md): what `--robustness` and `execute` draw
// perturbed worlds from. Relative for mass and friction, metres and degrees for poses; all 0 by default.
struct Uncertainty {
  double mass = 0.0;          // each movable body's mass times U[1 - mass, 1 + mass]
  double friction = 0.0;      // each movable body's floor friction times U[1 - friction, 1 + friction]
  double start = 0.0;         // m: the robot's start, uniform in a disc of this radius
  double body_pose = 0.0;     // m: each movable body's position, uniform in a disc of this radius
  double body_yaw_deg = 0.0;  // deg: each movable body's heading, uniform in [-body_yaw_deg, body_yaw_deg]
  Location where{};

  bool none() const { return mass == 0 && friction == 0 && start == 0 && body_pose == 0 && body_yaw_deg == 0; }
};

struct World {
  std::string name;  // file stem, names the output folder
  std::string source_file;
  // Every file the World was made from: the scenario, each module it required, each mesh, in that order.
  std::vector<std::string> inputs;
  Workspace workspace;
  Robot robot;
  std::vector<FixedBody> fixed_bodies;
  std::vector<MovableBody> movable_bodies;
  std::vector<Region> regions;
  std::vector<Group> groups;
  Task task;
  PlannerSettings planner;
  RenderSettings render;
  Uncertainty uncertainty;
  std::optional<Expectations> expect;  // the top-level file's expect { ... }, for `physltl-studio test`
};

// The most bodies of a kind a scenario may hold: beyond the warehouses logistics users simulate (6,400
// boxes: docs/benchmarks.md), and few enough that loading and validation stay under a second.
inline constexpr int kMaxFixedBodies = 2000;
inline constexpr int kMaxMovableBodies = 10000;
inline constexpr int max_bodies_of_kind(const std::string_view kind) { return kind == "movable" ? kMaxMovableBodies : kMaxFixedBodies; }

// A number as messages show it: six significant digits, 1e+300 rather than 301 of them.
std::string number_text(double value);

// What is wrong with `value` as a number from lo to hi (lo itself allowed or not), in words ("must be
// finite", "must be greater than 0, got -1", "is too large (1e+309 > 10000)"); nothing when it is fine.
// Scenarios, the command line and the files the program reads back all check numbers with it.
std::optional<std::string> number_problem(double value, double lo, double hi, bool lo_allowed = false);

// Where a body or region is among the World's, by name: World::movable_bodies or World::regions index,
// or -1 when it has none of that name. Every name the task or a picture uses is turned into an index here.
int movable_body_index(const World& world, std::string_view name);
int region_index(const World& world, std::string_view name);
// What the body part of an object atom names (a movable body, or a group of them) as World::movable_bodies
// indices, and what its region part names (a region, or a group of them) as World::regions indices, in
// the group's order; empty for a name that is neither, or a group member that is unknown.
std::vector<int> bodies_named(const World& world, std::string_view name);
std::vector<int> regions_named(const World& world, std::string_view name);

}  // namespace physltl::scenario
