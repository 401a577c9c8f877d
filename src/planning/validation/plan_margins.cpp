#include "plan_margins.h"

#include "physltl/geometry/free_space.h"

#include <algorithm>

namespace physltl::planning {

std::optional<double> clearance(const scenario::World& world, const scenario::StateTrace& states, std::size_t from,
                                std::size_t to, double cap, const Deadline& deadline) {
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

std::vector<double> visit_depths(const scenario::World& world, const Replay& replay) {
  const std::vector<int>& regions = replay.region_trace;
  std::vector<double> depths;
  for (std::size_t s = 1; s < replay.automaton_trace.size() && s < regions.size(); ++s) {
    const bool advanced = replay.automaton_trace[s] != replay.automaton_trace[s - 1];
    const bool entered = regions[s] >= 0 && regions[s] != regions[s - 1];
    const bool facts_same = s >= replay.facts_trace.size() || replay.facts_trace[s] == replay.facts_trace[s - 1];
    if (!advanced || !entered || !facts_same) continue;
    const geometry::Polygon& region = world.regions[static_cast<std::size_t>(regions[s])].polygon;
    double deepest = 0.0;
    for (std::size_t i = s; i < regions.size() && regions[i] == regions[s]; ++i) {
      deepest = std::max(deepest, geometry::depth_inside(replay.states.robot_position(i), region));
    }
    depths.push_back(deepest);
  }
  return depths;
}

}  // namespace physltl::planning
