#include "physltl/scenario/load.h"

#include "shape_kinds.h"

#include "physltl/ltl/object_atom.h"
#include "physltl/ltl/parser.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <optional>
#include <set>
#include <utility>
#include <vector>

namespace physltl::scenario {
namespace {

// Beyond these a scenario is a typo, not a world: SI units for a mobile robot in rooms.
constexpr double kMaxLength = 1e4;  // m
constexpr double kMaxMass = 1e6;    // kg
// Below these the physics engine fails (ODE asserts on a denormal mass, and on the contact matrix of a
// millimetre's body pressed between others): ten grams and a centimetre are no body a mobile robot pushes.
constexpr double kMinMass = 0.01;    // kg
constexpr double kMinLength = 0.01;  // m
constexpr double kMaxForce = 1e6;   // N
constexpr double kMaxFriction = 100.0;
constexpr double kMaxSpeed = 20.0;  // m/s: a mobile robot among boxes, and a bound on tunnelling per step
constexpr double kMaxTurnRateDeg = 3600.0;  // deg/s: ten turns a second
constexpr double kDegree = std::numbers::pi / 180.0;

// [a-z_][a-zA-Z0-9_]* (with `lower_first`) or [a-zA-Z_][a-zA-Z0-9_]*, checked by hand: std::regex recurses
// per character and overflows the stack on the long names a script can make.
bool is_word(const std::string& name, bool lower_first) {
  const auto word_char = [](char c) { return c == '_' || std::isalnum(static_cast<unsigned char>(c)); };
  const auto first = static_cast<unsigned char>(name.empty() ? '0' : name[0]);
  return (first == '_' || (lower_first ? std::islower(first) : std::isalpha(first))) && std::all_of(name.begin(), name.end(), word_char);
}
bool is_proposition_name(const std::string& name) { return is_word(name, true); }

class Validator {
 public:
  explicit Validator(const World& world) : world_(world) {}

  std::vector<Diagnostic> check_only_uncertainty(const Uncertainty& u) {
    check_uncertainty(u);
    return std::move(out_);
  }

  std::vector<Diagnostic> run() {
    check_workspace();
    check_robot();
    for (const auto& b : world_.fixed_bodies) check_body_shape("fixed '" + b.name + "'", b.footprint, b.height, b.where);
    for (const auto& b : world_.movable_bodies) check_movable(b);
    check_body_overlaps();
    check_regions();
    check_groups();
    check_task();
    check_planner();
    check_render();
    check_uncertainty(world_.uncertainty);
    return std::move(out_);
  }

 private:
  void error(const Location& where, const std::string& message) { out_.push_back({where, message}); }

  // One range check for every scalar: finite, inside [lo, hi], with `lo` itself allowed or not.
  void check_range(const Location& where, const std::string& what, double value, double lo, double hi,
                   bool lo_allowed = false) {
    if (const auto problem = number_problem(value, lo, hi, lo_allowed)) error(where, what + " " + *problem);
  }

  // A positive, finite value that must not be smaller than `smallest` (checked after its range).
  void check_not_tiny(const Location& where, const std::string& what, double value, double smallest, const char* unit) {
    if (std::isfinite(value) && value > 0.0 && value < smallest) {
      error(where, what + " is too small for the physics (" + fmt(value) + " < " + fmt(smallest) + " " + unit + ")");
    }
  }

  static std::string fmt(double v) { return number_text(v); }

  bool workspace_ok() const {
    const auto& b = world_.workspace.bounds;
    return b.min.allFinite() && b.max.allFinite() && (b.max - b.min).minCoeff() > 0;
  }

  void check_workspace() {
    const auto& w = world_.workspace;
    if (w.where.file.empty()) return;  // missing: reported by the reader
    const geometry::Vec2 size = w.bounds.max - w.bounds.min;
    if (!workspace_ok()) {
      error(w.where, "workspace: 'bounds' must go from the smaller corner to the larger one");
    } else if (size.maxCoeff() > kMaxLength || w.bounds.min.cwiseAbs().maxCoeff() > kMaxLength ||
               w.bounds.max.cwiseAbs().maxCoeff() > kMaxLength) {
      error(w.where, "workspace: 'bounds' reach beyond " + fmt(kMaxLength) + " m");
    }
    check_range(w.where, "workspace: 'floor_friction'", w.floor_friction, 0.0, kMaxFriction, true);
  }

  void check_robot() {
    const auto& r = world_.robot;
    if (r.where.file.empty()) return;
    check_range(r.where, "robot: 'radius'", r.radius, 0.0, kMaxLength);
    check_not_tiny(r.where, "robot: 'radius'", r.radius, kMinLength, "m");
    check_range(r.where, "robot: 'mass'", r.mass, 0.0, kMaxMass);
    check_not_tiny(r.where, "robot: 'mass'", r.mass, kMinMass, "kg");
    check_range(r.where, "robot: 'max_force'", r.max_force, 0.0, kMaxForce);
    check_range(r.where, "robot: 'max_speed'", r.max_speed, 0.0, kMaxSpeed);
    check_range(r.where, "robot: 'max_turn_rate_deg'", r.max_turn_rate / kDegree, 0.0, kMaxTurnRateDeg);
    check_range(r.where, "robot: 'friction'", r.friction, 0.0, kMaxFriction, true);
    if (!workspace_ok() || !(r.radius > 0)) return;
    const auto& b = world_.workspace.bounds;
    if ((r.start - b.min).minCoeff() < r.radius || (b.max - r.start).minCoeff() < r.radius) {
      error(r.where, "robot: 'start' must keep the robot (radius " + fmt(r.radius) + ") inside the workspace");
    }
    for (const auto& f : world_.fixed_bodies) {
      if (geometry::overlap(f.footprint.shape, f.footprint.pose, r.start, r.radius)) {
        error(r.where, "robot: 'start' is inside fixed '" + f.name + "' (" + f.where.str() + ")");
      }
    }
    for (const auto& m : world_.movable_bodies) {
      if (geometry::overlap(m.footprint.shape, m.footprint.pose, r.start, r.radius)) {
        error(r.where, "robot: 'start' is inside movable '" + m.name + "' (" + m.where.str() + ")");
      }
    }
  }

  void check_body_shape(const std::string& what, const geometry::Footprint& footprint, double height,
                        const Location& where) {
    const geometry::Shape& shape = footprint.shape;
    kind_of(shape).check_size(
        shape,
        [&](const std::string& length, double value) {
          check_range(where, what + ": " + length, value, 0.0, kMaxLength);
          check_not_tiny(where, what + ": " + length, value, kMinLength, "m");
        },
        [&] { error(where, what + " is too large"); }, kMaxLength);
    check_range(where, what + ": 'height'", height, 0.0, kMaxLength);
    check_not_tiny(where, what + ": 'height'", height, kMinLength, "m");
    if (footprint.pose.position.cwiseAbs().maxCoeff() > kMaxLength) error(where, what + ": 'center' is too far away");
    if (workspace_ok() && kind_of(shape).placeable(shape) && !geometry::inside(shape, footprint.pose, world_.workspace.bounds, 1e-6)) {
      error(where, what + " reaches outside the workspace");
    }
  }

  void check_movable(const MovableBody& b) {
    const std::string what = "movable '" + b.name + "'";
    check_body_shape(what, b.footprint, b.height, b.where);
    check_range(b.where, what + ": 'mass'", b.mass, 0.0, kMaxMass);
    check_not_tiny(b.where, what + ": 'mass'", b.mass, kMinMass, "kg");
    check_range(b.where, what + ": 'friction'", b.friction, 0.0, kMaxFriction, true);
    if (b.mregion_depth) check_range(b.where, what + ": 'mregion_depth'", *b.mregion_depth, 0.0, kMaxLength);
    // The same ranges as uncertainty { ... }.
    const auto& u = b.uncertainty;
    if (u.mass) check_range(b.where, what + ": uncertainty 'mass'", *u.mass, 0.0, 0.9, true);
    if (u.friction) check_range(b.where, what + ": uncertainty 'friction'", *u.friction, 0.0, 0.9, true);
    if (u.pose) check_range(b.where, what + ": uncertainty 'pose'", *u.pose, 0.0, 1.0, true);
    if (u.yaw_deg) check_range(b.where, what + ": uncertainty 'yaw_deg'", *u.yaw_deg, 0.0, 180.0, true);
    std::set<int> seen;
    for (int face : b.push_from) {
      if (!seen.insert(face).second) {
        error(b.where, what + ": 'push_from' lists " + face_name(b.footprint.shape, face) + " twice");
      }
    }
  }

  template <class Bodies>
  static std::vector<geometry::Rect> bounds_of(const Bodies& bodies) {
    std::vector<geometry::Rect> bounds;
    for (const auto& b : bodies) bounds.push_back(geometry::bounds(b.footprint.shape, b.footprint.pose));
    return bounds;
  }

  // Pairs (i, j) of a body of `a` and one of `b` whose bounds meet, sorted: a sweep along x, so that
  // thousands of bodies cost what their neighbours cost, not every pair. With `b` null, pairs within `a`,
  // each once with the later body first.
  static std::vector<std::pair<size_t, size_t>> close_pairs(const std::vector<geometry::Rect>& a,
                                                            const std::vector<geometry::Rect>* b = nullptr) {
    struct Item {
      const geometry::Rect* bounds;
      bool of_b;
      size_t index;
    };
    std::vector<Item> items;
    for (size_t i = 0; i < a.size(); ++i) items.push_back({&a[i], false, i});
    for (size_t j = 0; b != nullptr && j < b->size(); ++j) items.push_back({&(*b)[j], true, j});
    std::sort(items.begin(), items.end(), [](const Item& x, const Item& y) { return x.bounds->min.x() < y.bounds->min.x(); });
    std::vector<std::pair<size_t, size_t>> pairs;
    for (size_t k = 0; k < items.size(); ++k) {
      const Item& x = items[k];
      for (size_t l = k + 1; l < items.size() && items[l].bounds->min.x() <= x.bounds->max.x(); ++l) {
        const Item& y = items[l];
        if (y.bounds->min.y() > x.bounds->max.y() || y.bounds->max.y() < x.bounds->min.y()) continue;
        if (b == nullptr) {
          pairs.push_back({std::max(x.index, y.index), std::min(x.index, y.index)});
        } else if (x.of_b != y.of_b) {
          pairs.push_back(x.of_b ? std::pair{y.index, x.index} : std::pair{x.index, y.index});
        }
      }
    }
    std::sort(pairs.begin(), pairs.end());  // reported in the order of the file
    return pairs;
  }

  void check_body_overlaps() {
    std::map<std::string, Location> names;
    auto check_name = [&](const std::string& name, const Location& where) {
      auto [it, fresh] = names.emplace(name, where);
      if (!fresh) error(where, "body name '" + name + "' is used twice (also at " + it->second.str() + ")");
      if (name.find('@') != std::string::npos) {
        error(where, "body name '" + name + "' holds '@', which the formula reads as BODY@REGION: rename the body");
      }
    };
    const auto& fixed = world_.fixed_bodies;
    const auto& movable = world_.movable_bodies;
    for (const auto& f : fixed) check_name(f.name, f.where);
    const std::vector<geometry::Rect> fixed_bounds = bounds_of(fixed), movable_bounds = bounds_of(movable);
    for (const auto& [i, j] : close_pairs(fixed_bounds)) {
      if (geometry::overlap(fixed[i].footprint, fixed[j].footprint, 1e-6)) {
        error(fixed[i].where, "fixed '" + fixed[i].name + "' overlaps fixed '" + fixed[j].name + "' (" +
                                  fixed[j].where.str() + ")");
      }
    }
    // Each movable body's name, then the fixed bodies it overlaps, in the order of the file.
    const std::vector<std::pair<size_t, size_t>> near_fixed = close_pairs(movable_bounds, &fixed_bounds);
    auto pair = near_fixed.begin();
    for (size_t i = 0; i < movable.size(); ++i) {
      const auto& m = movable[i];
      check_name(m.name, m.where);
      for (; pair != near_fixed.end() && pair->first == i; ++pair) {
        const auto& f = fixed[pair->second];
        if (geometry::overlap(m.footprint, f.footprint, 1e-6)) {
          error(m.where, "movable '" + m.name + "' overlaps fixed '" + f.name + "' (" + f.where.str() + ")");
        }
      }
    }
    for (const auto& [i, j] : close_pairs(movable_bounds)) {
      if (geometry::overlap(movable[i].footprint, movable[j].footprint, 1e-6)) {
        error(movable[i].where, "movable '" + movable[i].name + "' overlaps movable '" + movable[j].name + "' (" +
                                    movable[j].where.str() + ")");
      }
    }
  }

  void check_regions() {
    static const std::set<std::string> reserved = {"p0", "true", "false", "X", "F", "G", "U", "R", "W", "M"};
    std::map<std::string, Location> names;
    const auto& regions = world_.regions;
    for (size_t i = 0; i < regions.size(); ++i) {
      const auto& r = regions[i];
      const std::string what = "region '" + r.name + "'";
      if (!is_proposition_name(r.name)) {
        error(r.where, what + ": a region name must start with a lower-case letter or '_' and hold only letters, "
                              "digits and '_' (it is a proposition in the formula)");
      } else if (reserved.count(r.name)) {
        error(r.where, what + ": the name is reserved (p0 means 'outside every region')");
      }
      auto [it, fresh] = names.emplace(r.name, r.where);
      if (!fresh) error(r.where, "region name '" + r.name + "' is used twice (also at " + it->second.str() + ")");
      if (r.polygon.vertices.size() < 3 || !r.polygon.is_simple()) {
        error(r.where, what + ": the polygon must have at least 3 corners, a positive area and no crossing edges");
        continue;
      }
      if (r.polygon.bounds().min.cwiseAbs().maxCoeff() > kMaxLength || r.polygon.bounds().max.cwiseAbs().maxCoeff() > kMaxLength) {
        error(r.where, what + " is too far away");
      } else if (workspace_ok() && !geometry::inside(r.polygon, world_.workspace.bounds, 1e-6)) {
        error(r.where, what + " reaches outside the workspace");
      }
      for (size_t j = 0; j < i; ++j) {
        if (regions[j].polygon.vertices.size() >= 3 && geometry::overlap(r.polygon, regions[j].polygon)) {
          error(r.where, what + " overlaps region '" + regions[j].name + "' (" + regions[j].where.str() +
                             "): regions must be disjoint");
        }
      }
    }
  }

  // A group: a word the formula can use, no name another body, region or group has, members that exist
  // (movable bodies only: a fixed one never moves), each once.
  void check_groups() {
    std::map<std::string, Location> names;
    for (const Group& g : world_.groups) {
      const std::string what = "group '" + g.name + "'";
      if (!is_word(g.name, false)) {
        error(g.where, what + ": a group name must start with a letter or '_' and hold only letters, digits and '_' "
                              "(it is part of a proposition in the formula)");
      }
      if (movable_body_index(world_, g.name) >= 0 || region_index(world_, g.name) >= 0 ||
          std::any_of(world_.fixed_bodies.begin(), world_.fixed_bodies.end(), [&](const FixedBody& b) { return b.name == g.name; })) {
        error(g.where, what + ": a body or region already has that name");
      }
      auto [it, fresh] = names.emplace(g.name, g.where);
      if (!fresh) error(g.where, "group name '" + g.name + "' is used twice (also at " + it->second.str() + ")");
      const bool of_bodies = !g.bodies.empty();
      std::set<std::string> seen;
      for (const std::string& member : of_bodies ? g.bodies : g.regions) {
        if (!seen.insert(member).second) error(g.where, what + " lists '" + member + "' twice");
        if (of_bodies && movable_body_index(world_, member) < 0) {
          error(g.where, what + ": '" + member + "' is no movable body (" + known_movable_bodies() + ")");
        } else if (!of_bodies && region_index(world_, member) < 0) {
          error(g.where, what + ": '" + member + "' is no region (" + known_regions() + ")");
        }
      }
    }
  }

  std::string known_regions() const {
    std::string known;
    for (const auto& r : world_.regions) known += (known.empty() ? "" : ", ") + r.name;
    return known.empty() ? "the scenario has no regions" : "known regions: " + known;
  }
  std::string known_movable_bodies() const {
    std::string known;
    for (const auto& b : world_.movable_bodies) known += (known.empty() ? "" : ", ") + b.name;
    return known.empty() ? "the scenario has no movable bodies" : "movable bodies: " + known;
  }
  bool is_group(const std::string& name, bool of_bodies) const {
    return std::any_of(world_.groups.begin(), world_.groups.end(),
                       [&](const Group& g) { return g.name == name && (of_bodies ? !g.bodies.empty() : !g.regions.empty()); });
  }

  // The formula (parsed by the reader, which reports a syntax error) must name only regions and bodies of
  // this scenario, or their groups; and what the automaton assumes must hold (check_exclusive_places).
  void check_task() {
    const auto& t = world_.task;
    if (t.where.file.empty()) return;  // missing: reported by the reader
    const std::string what = "task: formula '" + t.formula + "'";
    std::vector<ltl::ObjectAtom> objects;
    for (const std::string& p : ltl::propositions(t.parsed)) {
      if (const std::optional<ltl::ObjectAtom> object = ltl::object_atom(p)) {
        if (check_object_atom(what, p, *object)) objects.push_back(*object);
      } else if (is_group(p, false)) {
        error(t.where, what + " names region group '" + p + "' alone: the robot is in one region at a time, so its "
                                   "propositions name one region each (groups are for BODY@REGIONS)");
      } else {
        check_region_named(what, p);
      }
    }
    check_exclusive_places(what, objects);
  }

  void check_region_named(const std::string& what, const std::string& name) {
    if (region_index(world_, name) >= 0) return;
    error(world_.task.where, what + " names unknown region '" + name + "' (" + known_regions() + ")");
  }

  // BODY@REGION: a movable body of this scenario (or a group of them) and one of its regions (or a group of
  // them). Whether both are known.
  bool check_object_atom(const std::string& what, const std::string& atom, const ltl::ObjectAtom& object) {
    const Location& where = world_.task.where;
    const auto named = [&](const auto& body) { return body.name == object.body; };
    bool known = true;
    if (std::any_of(world_.fixed_bodies.begin(), world_.fixed_bodies.end(), named)) {
      error(where, what + ": '" + atom + "' names fixed '" + object.body + "', which never moves: object propositions " +
                       "are about movable bodies");
      known = false;
    } else if (movable_body_index(world_, object.body) < 0 && !is_group(object.body, true)) {
      error(where, what + ": '" + atom + "' names unknown body '" + object.body + "' (" + known_movable_bodies() + ")");
      known = false;
    }
    if (region_index(world_, object.region) < 0 && !is_group(object.region, false)) {
      check_region_named(what, object.region);
      known = false;
    }
    return known;
  }

  // The automaton takes a body (or a group) to be in at most one of the regions the task names it with,
  // and the planners give each body one such name: so the region sets one body part is named with must
  // not share a region, and no body may be named both alone and in a group, or in two groups.
  void check_exclusive_places(const std::string& what, const std::vector<ltl::ObjectAtom>& objects) {
    const Location& where = world_.task.where;
    std::map<std::string, std::vector<std::string>> regions_of_part;
    for (const ltl::ObjectAtom& o : objects) regions_of_part[o.body].push_back(o.region);
    std::map<int, std::string> part_of_body;
    for (const auto& [part, region_names] : regions_of_part) {
      std::map<int, std::string> named_with;
      for (const std::string& r : region_names) {
        for (int region : regions_named(world_, r)) {
          auto [it, fresh] = named_with.emplace(region, r);
          if (!fresh && it->second != r) {
            error(where, what + ": " + part + "@" + it->second + " and " + part + "@" + r + " share region '" +
                             world_.regions[static_cast<std::size_t>(region)].name + "': the regions one body or group " +
                             "is named with must not overlap");
          }
        }
      }
      for (int body : bodies_named(world_, part)) {
        auto [it, fresh] = part_of_body.emplace(body, part);
        if (!fresh) {
          error(where, what + ": " + world_.movable_bodies[static_cast<std::size_t>(body)].name + " is named both as " +
                           it->second + " and as " + part + ": name each body alone or in one group");
        }
      }
    }
  }

  void check_planner() {
    const auto& p = world_.planner;
    check_range(p.where, "planner: 'time_limit'", p.time_limit, 0.0, 1e6);
    check_range(p.where, "planner: 'step_size'", p.step_size, 0.0, 1.0);
    check_range(p.where, "planner: 'min_steps'", p.min_steps, 1.0, 1e4, true);
    check_range(p.where, "planner: 'max_steps'", p.max_steps, 1.0, 1e4, true);
    if (p.min_steps > p.max_steps) error(p.where, "planner: 'min_steps' must not exceed 'max_steps'");
    check_range(p.where, "planner: 'improve_margin'", p.improve_margin, 0.0, 1.0, true);
    check_range(p.where, "planner: 'max_overlap'", p.max_overlap, 0.0, kMaxOverlapLimit);
  }

  void check_uncertainty(const Uncertainty& u) {
    // A relative spread of 1 or more could make a mass or a friction zero or negative.
    check_range(u.where, "uncertainty: 'mass'", u.mass, 0.0, 0.9, true);
    check_range(u.where, "uncertainty: 'friction'", u.friction, 0.0, 0.9, true);
    check_range(u.where, "uncertainty: 'start'", u.start, 0.0, 1.0, true);
    check_range(u.where, "uncertainty: 'body_pose'", u.body_pose, 0.0, 1.0, true);
    check_range(u.where, "uncertainty: 'body_yaw_deg'", u.body_yaw_deg, 0.0, 180.0, true);
  }

  void check_render() {
    const auto& r = world_.render;
    check_range(r.where, "render: 'width'", r.width, 16.0, 8192.0, true);
    check_range(r.where, "render: 'height'", r.height, 16.0, 8192.0, true);
    check_range(r.where, "render: 'fps'", r.fps, 1.0, 240.0, true);
    check_range(r.where, "render: camera 'distance'", r.camera.distance, 0.0, kMaxLength, true);
    check_range(r.where, "render: camera 'elevation_deg'", r.camera.elevation_deg, 0.0, 90.0, true);
    if (r.camera.azimuth_deg) check_range(r.where, "render: camera 'azimuth_deg'", *r.camera.azimuth_deg, -360.0, 360.0, true);
    check_range(r.where, "render: camera 'fov_deg'", r.camera.fov_deg, 1.0, 170.0, true);
  }

  const World& world_;
  std::vector<Diagnostic> out_;
};

}  // namespace

std::vector<Diagnostic> validate(const World& world) { return Validator(world).run(); }

std::vector<Diagnostic> validate_uncertainty(const Uncertainty& uncertainty) {
  return Validator(World{}).check_only_uncertainty(uncertainty);
}

}  // namespace physltl::scenario
