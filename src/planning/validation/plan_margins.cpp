#include "plan_margins.h"

#include "physltl/geometry/free_space.h"

#include <algorithm>

namespace physltl::planning {

std::optional<double> clearance(const scenario::World& world, const scenario::StateTrace& states, std::size_t from,
                                std::size_t to, double cap, const base::Deadline& deadline) {
  to = std::min(to, states.size() - 1);
  if (from > to) return cap;
  geometry::Rect swept{states.robot_position(from), states.robot_position(from)};
  for (std::size_t i = from; i <= to; ++i) {
    swept.min = swept.min.cwiseMin(states.robot_position(i));
    swept.max = swept.max.cwiseMax(states.robot_position(i));
  }
  const Vec2 reach = Vec2::Constant(cap + world.robot.radius);
  std::vector<const scenario::FixedBody*> near;
  for (const scenario::FixedBody& body : world.fixed_bodies) {
    const geometry::Rect b = geometry::bounds(body.footprint.shape, body.footprint.pose);
    if ((b.min.array() <= (swept.max + reach).array()).all() && (b.max.array() >= (swept.min - reach).array()).all()) {
      near.push_back(&body);
    }
  }
  double least = cap;
  for (std::size_t i = from; i <= to; ++i) {
    if (deadline.reached()) return std::nullopt;
    const Vec2 robot = states.robot_position(i);
    for (const scenario::FixedBody* body : near) {
      least = std::min(least, geometry::distance(body->footprint.shape, body->footprint.pose, robot) - world.robot.radius);
    }
  }
  return least;
}

namespace {

// The deepest `where(i)` goes into `region` from step `s` on, while it stays in it.
template <class Where>
double deepest_stay(const scenario::World& world, int region, std::size_t s, std::size_t steps, Where where) {
  const geometry::Polygon& polygon = world.regions[static_cast<std::size_t>(region)].polygon;
  double deepest = 0.0;
  for (std::size_t i = s; i < steps; ++i) {
    const double depth = geometry::depth_inside(where(i), polygon);
    if (depth <= 0.0) break;
    deepest = std::max(deepest, depth);
  }
  return deepest;
}

}  // namespace

std::vector<double> visit_depths(const scenario::World& world, const Replay& replay, const knowledge::Labelling& labelling) {
  const std::vector<int>& regions = replay.region_trace;
  const scenario::StateTrace& states = replay.states;
  const std::size_t steps = std::min(regions.size(), states.size());
  const knowledge::RegionMap region_map(world);
  std::vector<double> depths;
  for (std::size_t s = 1; s < replay.automaton_trace.size() && s < steps; ++s) {
    if (replay.automaton_trace[s] == replay.automaton_trace[s - 1]) continue;
    const bool facts_changed = s < replay.facts_trace.size() && replay.facts_trace[s] != replay.facts_trace[s - 1];
    if (!facts_changed) {
      if (regions[s] < 0 || regions[s] == regions[s - 1]) continue;
      depths.push_back(deepest_stay(world, regions[s], s, steps, [&](std::size_t i) { return states.robot_position(i); }));
      continue;
    }
    for (std::size_t body = 0; body < world.movable_bodies.size(); ++body) {
      if (labelling.part_of(static_cast<int>(body)) < 0) continue;
      const int region = region_map.at(states.body_pose(body, s).position);
      if (region < 0) continue;
      depths.push_back(deepest_stay(world, region, s, steps, [&](std::size_t i) { return states.body_pose(body, i).position; }));
    }
  }
  return depths;
}

}  // namespace physltl::planning
