#include "physltl/execution/replanner.h"

#include "physltl/planning/planning_problem.h"

#include <memory>

namespace physltl::execution {

Replanned replan(const scenario::World& from_here, const planning::PlannerEntry& planner,
                 const planning::PlannerOptions& options, long long budget) {
  Replanned out;
  const planning::PlanningProblem problem(from_here);
  if (!problem.feasible()) {
    out.stop_reason = "infeasible: " + problem.reasoning().task.infeasibility();
    return out;
  }
  if (const auto why = planning::cannot_take(planner, problem.search_task(planner), {.propagation_budget = true})) {
    out.stop_reason = "refused: " + *why;
    return out;
  }
  // The budget, not the clock, ends the search: the time limit only guards against a budget too large,
  // and of the run's deadline only its stop flag (Ctrl-C) holds.
  planning::PlannerOptions budgeted = options;
  budgeted.deadline = base::Deadline::in(3600.0, options.deadline.stop());
  budgeted.max_propagations = budget;
  budgeted.threads = 1;
  const planning::ValidatedPlan solution = planning::solve(problem, planner, budgeted);
  out.propagations = solution.result.stats.propagations;
  out.planning_s = solution.result.stats.planning_time_s;
  out.stop_reason = planning::to_string(solution.result.stop_reason);
  if (solution.solved()) {
    out.plan = solution.result.plan;
    out.nominal = *solution.replay;
  }
  return out;
}

Replanner budgeted_replanner(const planning::PlannerEntry& planner, const planning::PlannerOptions& options, int world_index,
                             long long budget) {
  auto attempt = std::make_shared<std::uint64_t>(0);
  return [&planner, options, world_index, budget, attempt](const scenario::World& from_here) {
    planning::PlannerOptions replanning = options;
    replanning.seed = options.seed + 1'000'003ull * static_cast<std::uint64_t>(world_index + 1) + (*attempt)++;
    return replan(from_here, planner, replanning, budget);
  };
}

}  // namespace physltl::execution
