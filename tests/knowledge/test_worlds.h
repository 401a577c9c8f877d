#pragma once
// Small worlds built in code, so each test shows the geometry it relies on.

#include "physltl/geometry/convex_partition.h"
#include "physltl/knowledge/abstract_knowledge.h"
#include "physltl/knowledge/kappa.h"
#include "physltl/scenario/load.h"
#include "physltl/scenario/state.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace physltl::knowledge {

using scenario::Side;  // a box's sides, faces 0 to 3

namespace testing {

using geometry::Vec2;

// A square workspace [-half, half]^2 with no walls; robot of radius 0.25, 20 N, at `start`.
inline scenario::World open_world(double half = 3.0, Vec2 start = Vec2(-2.0, -2.0)) {
  scenario::World w;
  w.name = "test";
  w.workspace.bounds = {Vec2(-half, -half), Vec2(half, half)};
  w.workspace.floor_friction = 0.5;
  w.robot.radius = 0.25;
  w.robot.mass = 1.0;
  w.robot.max_force = 20.0;
  w.robot.friction = 0.5;
  w.robot.start = start;
  return w;
}

inline void add_wall(scenario::World& w, const std::string& name, Vec2 min, Vec2 max) {
  scenario::FixedBody f;
  f.name = name;
  f.footprint.pose.position = 0.5 * (min + max);
  f.footprint.shape = geometry::Shape::box(0.5 * (max - min));
  w.fixed_bodies.push_back(f);
}

inline scenario::MovableBody& add_box(scenario::World& w, const std::string& name, Vec2 center, Vec2 size,
                                      double mass = 0.5) {
  scenario::MovableBody b;
  b.name = name;
  b.footprint.pose.position = center;
  b.footprint.shape = geometry::Shape::box(0.5 * size);
  b.mass = mass;
  w.movable_bodies.push_back(b);
  return w.movable_bodies.back();
}

// A movable polygon of `corners` (world frame, any simple outline: concave ones are cut into convex parts
// as the scenario reader cuts them), its pose its area centroid.
inline scenario::MovableBody& add_polygon(scenario::World& w, const std::string& name, const std::vector<Vec2>& corners) {
  geometry::Polygon outline{corners};
  const Vec2 centroid = outline.centroid();
  for (Vec2& v : outline.vertices) v -= centroid;
  scenario::MovableBody body;
  body.name = name;
  body.mass = 1.0;
  body.footprint = {{centroid, 0.0}, geometry::Shape::polygon(outline, geometry::convex_partition(outline))};
  w.movable_bodies.push_back(body);
  return w.movable_bodies.back();
}

inline void add_region(scenario::World& w, const std::string& name, Vec2 min, Vec2 max) {
  w.regions.push_back({name, geometry::Polygon::from_rect({min, max}), {}});
}

inline scenario::World shipped_scenario(const std::string& file) {
  return scenario::load_scenario(std::string(PHYSLTL_SOURCE_DIR) + "/scenarios/" + file);
}

inline size_t movable_index(const scenario::World& w, const std::string& name) {
  auto it = std::find_if(w.movable_bodies.begin(), w.movable_bodies.end(), [&](auto& b) { return b.name == name; });
  if (it == w.movable_bodies.end()) throw std::runtime_error("no movable body " + name);
  return static_cast<size_t>(it - w.movable_bodies.begin());
}

// A box's side as the face number kappa and the mRegions use.
inline int face(scenario::Side side) { return static_cast<int>(side); }

// "-x +y": a box's active sides, in the order of scenario::Side, for readable expectations.
inline std::string sides(FaceSet set) {
  std::string out;
  for (int f = 0; f < 4; ++f) {
    if (set.contains(f)) out += (out.empty() ? "" : " ") + std::string(scenario::side_name(static_cast<scenario::Side>(f)));
  }
  return out;
}

}  // namespace testing
}  // namespace physltl::knowledge
