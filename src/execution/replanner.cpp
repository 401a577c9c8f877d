#include "physltl/execution/replanner.h"

#include "physltl/planning/planning_problem.h"

#include <memory>

namespace physltl::execution {

Replanned replan(const scenario::World& from_here, const planning::PlannerEntry& planner, std::uint64_t seed,
                 long long budget) {
  Replanned out;
  const planning::PlanningProblem problem(from_here);
  if (!problem.feasible()) {
    out.stop_reason = "infeasible: " + problem.reasoning().task.infeasibility();
    return out;
  }
  if (const auto why = problem.refusal(planner, {.propagation_budget = true})) {
    out.stop_reason = "refused: " + *why;
    return out;
  }
  // The budget, not the clock, ends the search: the time limit only guards against a budget too large.
  const planning::ValidatedPlan solution =
      planning::solve(problem, planner, {.seed = seed, .time_limit = 3600.0, .max_propagations = budget, .threads = 1});
  out.propagations = solution.result.stats.propagations;
  out.planning_s = solution.result.stats.planning_time_s;
  out.stop_reason = solution.result.stop_reason;
  if (solution.solved()) {
    out.plan = solution.result.plan;
    out.nominal = *solution.replay;
  }
  return out;
}

Replanner budgeted_replanner(const planning::PlannerEntry& planner, std::uint64_t seed, int world_index, long long budget) {
  auto attempt = std::make_shared<std::uint64_t>(0);
  return [&planner, seed, world_index, budget, attempt](const scenario::World& from_here) {
    const std::uint64_t replanning_seed =
        seed + 1'000'003ull * static_cast<std::uint64_t>(world_index + 1) + (*attempt)++;
    return replan(from_here, planner, replanning_seed, budget);
  };
}

}  // namespace physltl::execution
