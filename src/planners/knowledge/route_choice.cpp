#include "route_choice.h"

#include "physltl/geometry/shortest_paths.h"

#include "physltl/planning/stage_graph.h"

#include "physltl/geometry/convex_partition.h"
#include "physltl/geometry/rect_grid.h"
#include "physltl/planning/path_lower_bound.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <utility>

namespace physltl::planners::knowledge {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Per stage, the places (0: the start, k + 1: region k) the robot can enter it at: the start for the
// first stage, the region whose entry led into a stage, and for a stage a body move led into, the body's
// new region (the robot stands by it).
std::vector<std::set<int>> entry_places(const scenario::World& world, const planning::TaskAutomaton& task, const planning::StageGraph& stages) {
  std::vector<std::set<int>> entries(static_cast<size_t>(stages.stages()));
  const int first = stages.stage(task.start_state(scenario::EnvironmentState::initial(world)),
                                 task.labelling.facts(scenario::EnvironmentState::initial(world)));
  entries[static_cast<size_t>(first)].insert(0);
  std::deque<int> todo{first};
  std::vector<bool> seen(entries.size(), false);
  seen[static_cast<size_t>(first)] = true;
  const auto reach = [&](int next, int place) {
    if (entries[static_cast<size_t>(next)].insert(place).second || !seen[static_cast<size_t>(next)]) {
      seen[static_cast<size_t>(next)] = true;
      todo.push_back(next);
    }
  };
  while (!todo.empty()) {
    const int s = todo.front();
    todo.pop_front();
    for (int region = 0; region < task.labelling.regions(); ++region) {
      const int next = stages.after_robot(s, region);
      if (next != s) reach(next, region + 1);
    }
    if (const auto& move = stages.body_move(s)) {
      const physltl::knowledge::Labelling::NamedPart& part = task.labelling.named_parts()[static_cast<size_t>(move->named)];
      const int facts = task.labelling.with_place(stages.facts_of(s), move->named, move->place);
      const int next = stages.after_letter(s, task.labelling.letter(facts, -1));
      const std::set<int> from = entries[static_cast<size_t>(s)];
      if (move->place > 0) {
        for (int region : part.region_sets[static_cast<size_t>(move->place - 1)]) reach(next, region + 1);
      } else {
        for (int place : from) reach(next, place);
      }
    }
  }
  return entries;
}

// The places (k + 1: region k) whose entry brings a stage closer to acceptance; none for a stage that is
// accepting, lost, or waits for a body move.
std::vector<int> target_places(const planning::TaskAutomaton& task, const planning::StageGraph& stages, int s) {
  std::vector<int> targets;
  const int d = stages.distance(s);
  if (d <= 0 || stages.body_move(s)) return targets;
  for (int region = 0; region < task.labelling.regions(); ++region) {
    if (stages.distance(stages.after_robot(s, region)) == d - 1) targets.push_back(region + 1);
  }
  return targets;
}

// Shortest distances over the decomposition's triangles (between centroids) from `sources`, through the
// triangles `open` allows.
std::vector<double> triangle_distances(const decomposition::Decomposition& decomposition, const std::vector<int>& sources,
                                       const std::vector<bool>& open) {
  const auto& triangles = decomposition.triangles();
  geometry::ShortestPaths ways(triangles.size());
  for (int t : sources) ways.seed(t, 0.0);
  ways.run([&](int t, double d) {
    for (int n : triangles[static_cast<size_t>(t)].neighbors) {
      if (!open[static_cast<size_t>(n)]) continue;
      ways.relax(t, n, d + (triangles[static_cast<size_t>(n)].centroid - triangles[static_cast<size_t>(t)].centroid).norm());
    }
    return true;
  });
  return ways.distances();
}

// The triangles standing for a place: the start's, or every triangle of a region.
std::vector<int> place_triangles(const scenario::World& world, const decomposition::Decomposition& decomposition, int place) {
  if (place == 0) return {decomposition.locate(world.robot.start)};
  std::vector<int> triangles;
  for (int t = 0; t < decomposition.size(); ++t) {
    if (decomposition.triangles()[static_cast<size_t>(t)].region == place - 1) triangles.push_back(t);
  }
  return triangles;
}

// Per stage, the regions the robot may not enter there: entering one loses the task (the hazard under
// `G !hazard`, or before the goal in `!hazard U goal`).
std::vector<std::vector<int>> forbidden_regions(const planning::TaskAutomaton& task, const planning::StageGraph& stages) {
  std::vector<std::vector<int>> forbidden(static_cast<size_t>(stages.stages()));
  for (int s = 0; s < stages.stages(); ++s) {
    for (int region = 0; region < task.labelling.regions(); ++region) {
      if (stages.distance(stages.after_robot(s, region)) < 0) forbidden[static_cast<size_t>(s)].push_back(region);
    }
  }
  return forbidden;
}

// Shortest ways between the places, through the bodies and round them, for the robot's centre kept out of
// some regions. A push-free way needs kMinFreeWidth of room.
struct PlaceWays {
  std::vector<std::vector<double>> through, push_free;
};

PlaceWays place_ways(const scenario::World& world, const std::vector<int>& avoided_regions, const base::Deadline& deadline) {
  std::vector<geometry::Polygon> avoided;
  for (int region : avoided_regions) {
    for (geometry::Polygon& part : geometry::convex_partition(world.regions[static_cast<size_t>(region)].polygon)) {
      avoided.push_back(std::move(part));
    }
  }
  return {planning::place_distances(world, planning::robot_free_space(world, planning::RobotObstacles::kFixedBodies, 0.0, avoided), deadline),
          planning::place_distances(world, planning::robot_free_space(world, planning::RobotObstacles::kAllBodies, kMinFreeWidth, avoided), deadline)};
}

// Whether stage `s` goes round: from every place it is entered at, a push-free way to a region that brings
// the task closer is at most (1 + kDetourFactor) times the way through plus kDetourAllowance.
bool stage_goes_round(const std::set<int>& entries, const std::vector<int>& targets, const PlaceWays& ways) {
  bool goes_round = true, any_way = false;
  for (int from : entries) {
    double best_through = kInfinity, best_round = kInfinity;
    for (int target : targets) {
      best_through = std::min(best_through, ways.through[static_cast<size_t>(from)][static_cast<size_t>(target)]);
      best_round = std::min(best_round, ways.push_free[static_cast<size_t>(from)][static_cast<size_t>(target)]);
    }
    if (!std::isfinite(best_through)) continue;  // nothing gets there from here: no say
    any_way = true;
    goes_round = goes_round && best_round <= (1.0 + kDetourFactor) * best_through + kDetourAllowance;
  }
  return any_way && goes_round;  // with no say from anywhere, nothing is cut
}

}  // namespace

RouteChoice choose_routes(const scenario::World& world, const planning::TaskAutomaton& task, const planning::StageGraph& stages,
                          const decomposition::Decomposition& decomposition, const base::Deadline& deadline) {
  const int count = stages.stages();
  RouteChoice choice{std::vector<bool>(static_cast<size_t>(count), false), {}};
  const std::vector<bool> under = triangles_under_bodies(world, task, decomposition, deadline);
  if (std::none_of(under.begin(), under.end(), [](bool u) { return u; })) return choice;

  // The ways for each set of forbidden regions the stages have (geometry::FreeSpace, exact).
  const std::vector<std::vector<int>> forbidden = forbidden_regions(task, stages);
  std::map<std::vector<int>, PlaceWays> ways;
  const int places = task.labelling.regions() + 1;
  std::vector<std::vector<int>> triangles_of(static_cast<size_t>(places));
  for (int place = 0; place < places; ++place) triangles_of[static_cast<size_t>(place)] = place_triangles(world, decomposition, place);

  const std::vector<std::set<int>> entries = entry_places(world, task, stages);
  for (int s = 0; s < count; ++s) {
    const std::vector<int> targets = target_places(task, stages, s);
    if (targets.empty() || entries[static_cast<size_t>(s)].empty()) continue;
    const std::vector<int>& avoided = forbidden[static_cast<size_t>(s)];
    auto found = ways.find(avoided);
    if (found == ways.end()) found = ways.emplace(avoided, place_ways(world, avoided, deadline)).first;
    choice.going_round[static_cast<size_t>(s)] = stage_goes_round(entries[static_cast<size_t>(s)], targets, found->second);
  }
  if (std::none_of(choice.going_round.begin(), choice.going_round.end(), [](bool b) { return b; })) return choice;

  // In a stage that goes round, each state costs the lead more the longer the way through its triangle is
  // than the stage's shortest push-free way (kept out of the stage's forbidden regions), and a triangle
  // under a body kUnderBodyCost times more.
  choice.lead_factor.assign(static_cast<size_t>(decomposition.size()) * static_cast<size_t>(count), 1.0f);
  for (int s = 0; s < count; ++s) {
    if (!choice.going_round[static_cast<size_t>(s)]) continue;
    deadline.check();
    const std::vector<int>& avoided = forbidden[static_cast<size_t>(s)];
    std::vector<bool> clear(under.size());
    for (size_t t = 0; t < under.size(); ++t) {
      const int region = decomposition.triangles()[t].region;
      clear[t] = !under[t] && std::find(avoided.begin(), avoided.end(), region) == avoided.end();
    }
    std::vector<int> from;
    for (int place : entries[static_cast<size_t>(s)]) {
      for (int t : triangles_of[static_cast<size_t>(place)]) from.push_back(t);
    }
    std::vector<int> to;
    for (int target : target_places(task, stages, s)) {
      for (int t : triangles_of[static_cast<size_t>(target)]) to.push_back(t);
    }
    const std::vector<double> in = triangle_distances(decomposition, from, clear);
    const std::vector<double> out = triangle_distances(decomposition, to, clear);
    double shortest = kInfinity;
    for (int t : to) shortest = std::min(shortest, in[static_cast<size_t>(t)]);
    for (int t = 0; t < decomposition.size(); ++t) {
      const double extra = in[static_cast<size_t>(t)] + out[static_cast<size_t>(t)] - shortest;
      const double factor = (under[static_cast<size_t>(t)] ? kUnderBodyCost : 1.0) *
                            (std::isfinite(extra) ? 1.0 + std::max(0.0, extra) / kDetourLength : kUnderBodyCost);
      choice.lead_factor[static_cast<size_t>(t) * static_cast<size_t>(count) + static_cast<size_t>(s)] = static_cast<float>(factor);
    }
  }
  return choice;
}

std::vector<bool> triangles_under_bodies(const scenario::World& world, const planning::TaskAutomaton& task,
                                         const decomposition::Decomposition& decomposition, const base::Deadline& deadline) {
  std::vector<const geometry::Footprint*> bodies;
  std::vector<geometry::Rect> bounds;
  for (size_t b = 0; b < world.movable_bodies.size(); ++b) {
    const bool moved_on_purpose = task.labelling.part_of(static_cast<int>(b)) >= 0;
    if (moved_on_purpose) continue;
    const geometry::Footprint& f = world.movable_bodies[b].footprint;
    bodies.push_back(&f);
    bounds.push_back(geometry::bounds(f.shape, f.pose));
  }
  // Each triangle against the bodies within the robot's radius of its centroid only: a lookup, not a
  // scan of every body (a warehouse of 6,400 boxes has some 100,000 triangles).
  const geometry::RectGrid near(bounds, world.robot.radius);
  std::vector<bool> under;
  under.reserve(decomposition.triangles().size());
  for (const auto& triangle : decomposition.triangles()) {
    deadline.check();
    const std::span<const int> candidates = near.near(triangle.centroid);
    under.push_back(std::any_of(candidates.begin(), candidates.end(), [&](int b) {
      const geometry::Footprint& f = *bodies[static_cast<std::size_t>(b)];
      return geometry::overlap(f.shape, f.pose, triangle.centroid, world.robot.radius);
    }));
  }
  return under;
}

}  // namespace physltl::planners::knowledge
