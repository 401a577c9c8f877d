#include "lookahead.h"

#include "physltl/geometry/disc_field.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace physltl::planners::knowledge {

const char* direction_name(const PlannedPush& push) {
  return push.dx > 0 ? "+x" : push.dx < 0 ? "-x" : push.dy > 0 ? "+y" : "-y";
}

std::string describe(const PlannedPush& push, const std::vector<std::string>& body_names) {
  std::string bodies = body_names[static_cast<std::size_t>(push.body)];
  if (!push.ahead.empty()) {
    std::vector<std::string> ahead;
    for (int b : push.ahead) ahead.push_back(body_names[static_cast<std::size_t>(b)]);
    bodies += fmt::format(" (with {})", fmt::join(ahead, ", "));
  }
  return fmt::format("{} {} {:.2g} m", bodies, direction_name(push), push.distance);
}

namespace lookahead {
namespace {

// The room a named body's way must have everywhere, beyond the body's own side, for the robot to walk
// round the body there: a robot's diameter on either side.
constexpr double kRobotDiametersBeside = 2.0;
constexpr double kWayCell = 0.05;  // m: the grid of that check

// Why the look-ahead applies for World body `b`: it cannot get to `regions` with room for the robot beside
// it; nothing when it can (or cannot move at all).
std::optional<std::string> narrow_way_of(const scenario::World& world, const physltl::knowledge::AbstractKnowledge& knowledge, int b,
                                         const std::vector<int>& regions, const base::Deadline& deadline) {
  const auto& body = knowledge.movable_bodies[static_cast<std::size_t>(b)];
  if (body.body_class == physltl::knowledge::BodyClass::kFixed) return std::nullopt;
  std::vector<geometry::Footprint> obstacles;
  for (const auto& f : knowledge.fixed_bodies) obstacles.push_back(f.footprint);
  for (std::size_t other = 0; other < knowledge.movable_bodies.size(); ++other) {
    if (static_cast<int>(other) != b) obstacles.push_back(knowledge.movable_bodies[other].footprint);
  }
  // Across its centre at its narrowest: a box's shorter side, a disc's diameter; a concave body's centre
  // may lie near its inner corner or outside it, so its width is its bounds' narrower side.
  const geometry::Shape& shape = body.footprint.shape;
  const double side = shape.parts().size() > 1 ? geometry::bounds(shape, {}).size().minCoeff() : 2 * shape.centre_clearance();
  const double width = side + kRobotDiametersBeside * 2 * knowledge.robot.radius;
  const double cell = std::max(kWayCell, std::sqrt(knowledge.workspace.size().prod() / 250'000.0));
  geometry::DiscField wide(knowledge.workspace, cell, width / 2, obstacles, deadline);
  std::vector<const geometry::Polygon*> polygons;
  for (int r : regions) polygons.push_back(&world.regions[static_cast<std::size_t>(r)].polygon);
  wide.compute_distances(wide.cells_near(polygons, 0.0, deadline), deadline);
  if (wide.reaches_target(body.footprint.pose.position)) return std::nullopt;
  return fmt::format("{}'s way to its regions is narrower than {:.2f} m (its width {:.2f} m and two robot diameters) "
                     "among the walls and the other bodies",
                     body.name, width, side);
}

// Why the look-ahead applies: a named body cannot get to its regions with room for the robot beside it,
// among the walls and the other bodies where they stand (boxes side by side need an order as much as a
// corridor does). Nothing when every named body can.
std::optional<std::string> narrow_way(const scenario::World& world, const physltl::knowledge::AbstractKnowledge& knowledge,
                                      const physltl::knowledge::Labelling& labelling, const base::Deadline& deadline) {
  for (const physltl::knowledge::Labelling::NamedPart& named : labelling.named_parts()) {
    std::vector<int> regions;
    for (const std::vector<int>& set : named.region_sets) regions.insert(regions.end(), set.begin(), set.end());
    for (int b : named.bodies) {
      if (auto why = narrow_way_of(world, knowledge, b, regions, deadline)) return why;
    }
  }
  return std::nullopt;
}

}  // namespace

std::vector<PlannedPush> runs_of(const PushLattice& lattice, const std::vector<PushStep>& steps) {
  std::vector<PlannedPush> runs;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const PushStep& step = steps[i];
    const int body = lattice.bodies()[static_cast<std::size_t>(step.body)];
    if (!runs.empty() && i > 0 && same_run(steps[i - 1], step)) {
      runs.back().cells += 1;
      runs.back().distance = runs.back().cells * lattice.step();
      runs.back().to = lattice.body_centre(step.body, step.to);
      continue;
    }
    std::vector<int> ahead;
    for (int k : step.ahead) ahead.push_back(lattice.bodies()[static_cast<std::size_t>(k)]);
    runs.push_back({body, std::move(ahead), kDx[step.direction], kDy[step.direction], 1, lattice.step(),
                    lattice.body_centre(step.body, step.from), lattice.body_centre(step.body, step.to)});
  }
  return runs;
}

Lookahead look_ahead(const scenario::World& world, const physltl::knowledge::AbstractKnowledge& knowledge, const planning::TaskAutomaton& task,
                     const planning::StageGraph& stages, const base::Deadline& deadline, long long max_arrangements) {
  Lookahead result;
  PushPlan& plan = result.plan;
  if (!task.names_bodies()) {
    plan.rule.reason = "the task names no body";
    plan.outcome = "not searched";
    return result;
  }
  const std::optional<std::string> narrow = narrow_way(world, knowledge, task.labelling, deadline);
  if (!narrow) {
    plan.rule.reason = "every named body has room for the robot beside it all the way to its regions, among the walls and the other bodies";
    plan.outcome = "not searched";
    return result;
  }
  std::string why_not;
  result.lattice = PushLattice::build(world, knowledge, task.labelling, deadline, why_not);
  if (!result.lattice) {
    plan.rule.reason = *narrow + ", but " + why_not;
    plan.outcome = "not searched";
    return result;
  }
  plan.rule = {true, *narrow, result.lattice->step()};
  const scenario::EnvironmentState start = scenario::EnvironmentState::initial(world);
  const int letter = task.labelling.letter(start);
  result.stage = stages.stage(task.step(task.dfa.start, letter), task.labelling.facts_of(letter));
  result.start_cells = *result.lattice->arrangement(start);
  const int robot = result.lattice->robot_cell(start.robot_position);
  if (robot < 0) {
    plan.outcome = "the robot stands off the lattice";
    return result;
  }
  if (!stages.body_move(result.stage)) {
    plan.outcome = "the task's first move is the robot's";
    return result;
  }
  const PushSearch search =
      PushSearcher(*result.lattice, stages, task.labelling).search(result.stage, result.start_cells, robot, deadline, {max_arrangements});
  plan.arrangements = search.settled;
  plan.budget = max_arrangements;
  plan.outcome = search.outcome;
  plan.found = search.found;
  result.steps = search.steps;
  plan.pushes = runs_of(*result.lattice, search.steps);
  return result;
}

}  // namespace lookahead
}  // namespace physltl::planners::knowledge
