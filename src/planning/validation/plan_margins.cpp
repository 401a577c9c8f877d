#include "plan_margins.h"

#include "physltl/geometry/free_space.h"

#include <algorithm>
#include <limits>

namespace physltl::planning {

double clearance(const scenario::World& world, const scenario::StateTrace& states, std::size_t from, std::size_t to) {
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t i = from; i <= to && i < states.size(); ++i) {
    const Vec2 robot = states.robot_position(i);
    for (const scenario::FixedBody& body : world.fixed_bodies) {
      least = std::min(least, geometry::distance(body.footprint.shape, body.footprint.pose, robot) - world.robot.radius);
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
