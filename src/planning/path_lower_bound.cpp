#include "physltl/planning/path_lower_bound.h"

#include "physltl/geometry/shortest_paths.h"

#include <cmath>
#include <functional>
#include <limits>

namespace physltl::planning {
namespace {

// A relaxation of the task's product with the free space, small enough to search exactly: a place is the
// start or a region, and the robot moves from a place to a region at the free-space distance between them
// (any point of one to any point of the other), reading that region; reading "no region" is free. Any
// path the robot can follow reads its regions in some order, each leg at least that distance long, so the
// cheapest accepted order is a lower bound.
// `bodies_stay`: the bodies the task names keep their places (nothing is pushed); otherwise they may be
// anywhere at no cost.
double shortest_accepted_route(const scenario::World& world, const TaskAutomaton& task,
                               const std::vector<std::vector<double>>& leg, bool bodies_stay) {
  const int regions = static_cast<int>(world.regions.size());
  const int states = static_cast<int>(task.dfa.size());
  const auto id = [&](int place, int q) { return place * states + q; };
  geometry::ShortestPaths routes(leg.size() * static_cast<size_t>(states));
  const scenario::EnvironmentState initial = scenario::EnvironmentState::initial(world);
  const int facts_at_start = task.labelling.facts(initial);
  routes.seed(id(0, task.start_state(initial)), 0.0);
  const int accepted = routes.run([&](int u, double c) {
    const int place = u / states, q = u % states;
    if (task.dfa.accepting[static_cast<size_t>(q)]) return false;
    // Where the bodies may be anywhere at no cost (moving them takes the robot somewhere too, so this only
    // makes the bound lower), every fact set is tried.
    for (int facts = 0; facts < task.labelling.fact_sets(); ++facts) {
      if (bodies_stay && facts != facts_at_start) continue;
      routes.relax(u, id(place, task.step(q, task.labelling.letter(facts, -1))), c);
      for (int region = 0; region < regions; ++region) {
        routes.relax(u, id(region + 1, task.step(q, task.labelling.letter(facts, region))),
                     c + leg[static_cast<size_t>(place)][static_cast<size_t>(region + 1)]);
      }
    }
    return true;
  });
  return accepted < 0 ? std::numeric_limits<double>::infinity() : routes.distance(accepted);
}

// A robot braked against a wall or a box, or placed touching one, has its centre on or a hair inside the
// grown obstacle (physics contacts are soft: ODE lets a body sink about a millimetre into another); its
// start is then the free floor within kStartReach of that centre, or it would have no way anywhere.
constexpr double kStartReach = 0.02;

geometry::Polygon start_place(const geometry::FreeSpace& space, const geometry::Vec2& start) {
  if (space.free(start, start)) return geometry::Polygon{{start}};
  const geometry::Vec2 dx(kStartReach, 0.0), dy(0.0, kStartReach);
  return geometry::Polygon{{start - dx - dy, start + dx - dy, start + dx + dy, start - dx + dy}};
}

}  // namespace

geometry::FreeSpace robot_free_space(const scenario::World& world, RobotObstacles obstacles, double clearance,
                                     const std::vector<geometry::Polygon>& avoided) {
  const double r = world.robot.radius + clearance / 2.0;
  std::vector<geometry::Polygon> grown = avoided;
  const auto add = [&](const geometry::Footprint& f) {
    for (geometry::Polygon& part : geometry::grown_from_inside(f.shape, f.pose, r)) grown.push_back(std::move(part));
  };
  for (const auto& f : world.fixed_bodies) add(f.footprint);
  if (obstacles == RobotObstacles::kAllBodies) {
    for (const auto& m : world.movable_bodies) add(m.footprint);
  }
  const geometry::Rect bounds{world.workspace.bounds.min + geometry::Vec2::Constant(r),
                              world.workspace.bounds.max - geometry::Vec2::Constant(r)};
  return geometry::FreeSpace(std::move(grown), bounds);
}

std::vector<std::vector<double>> place_distances(const scenario::World& world, const geometry::FreeSpace& space,
                                                 const base::Deadline& deadline) {
  std::vector<geometry::Polygon> places{start_place(space, world.robot.start)};
  for (const auto& region : world.regions) places.push_back(region.polygon);
  return space.distances(places, deadline);
}

double shortest_free_path_length(const scenario::World& world, const TaskAutomaton& task, const base::Deadline& deadline) {
  const geometry::FreeSpace space = robot_free_space(world, RobotObstacles::kFixedBodies);
  return shortest_accepted_route(world, task, place_distances(world, space, deadline), false);
}

double shortest_push_free_path_length(const scenario::World& world, const TaskAutomaton& task, const base::Deadline& deadline) {
  const geometry::FreeSpace space = robot_free_space(world, RobotObstacles::kAllBodies);
  return shortest_accepted_route(world, task, place_distances(world, space, deadline), true);
}

double plan_cost_bound(const scenario::PlanCost& cost, double max_speed, double free_path_m, double push_free_path_m) {
  double bound = 0.0;
  if (cost.time > 0.0) bound += cost.time * free_path_m / max_speed;  // (0 x infinity is no bound)
  if (cost.length > 0.0) bound += cost.length * free_path_m;
  if ((cost.pushes > 0.0 || cost.moved > 0.0) && std::isinf(push_free_path_m)) bound += cost.pushes + cost.moved;
  return bound;
}

double plan_cost_bound(const scenario::World& world, const TaskAutomaton& task, const scenario::PlanCost& cost,
                       const base::Deadline& deadline) {
  // Only the ways the cost's terms need (a push-free way costs a free space of every body).
  const double free_path = cost.time > 0.0 || cost.length > 0.0 ? shortest_free_path_length(world, task, deadline) : 0.0;
  const double push_free = cost.pushes > 0.0 || cost.moved > 0.0 ? shortest_push_free_path_length(world, task, deadline) : 0.0;
  return plan_cost_bound(cost, world.robot.max_speed, free_path, push_free);
}

}  // namespace physltl::planning
