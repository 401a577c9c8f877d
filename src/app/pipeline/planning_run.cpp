#include "planning_run.h"

#include "physltl/common/bad_input.h"
#include "physltl/common/stop_signal.h"
#include "physltl/setup/planner_names.h"
#include "views/failed_search.h"
#include "physltl/planning/path_lower_bound.h"
#include "physltl/planning/validation/improve.h"

#include <cmath>

namespace physltl::app {

PlanningRun::PlanningRun(const scenario::World& world, const setup::RunSettings& settings, const planning::PlannerEntry& planner)
    : settings_(settings),
      deadline_(base::Deadline::in(settings.time_limit_s, &common::stop_flag())),
      problem_(world, settings.time_limit_s, deadline_),
      planner_(planner) {}

planning::ValidatedPlan PlanningRun::solve() const {
  return planning::solve(problem_, planner_, settings_.planner_options(deadline_), settings_.improvement);
}

void PlanningRun::require_plannable(planning::Needs needs) const {
  if (!problem_.feasible()) throw common::InfeasibleTask(problem_.reasoning().task.infeasibility());
  if (const auto why = setup::registry().refusal(planner_, problem_.search_task(planner_), needs)) throw common::BadInput(*why);
}

std::optional<PlanningRun::Failure> PlanningRun::failure(const planning::ValidatedPlan& solution,
                                                         const std::optional<std::filesystem::path>& failed_folder,
                                                         bool render) const {
  const planning::PlanResult& result = solution.result;
  if (!result.solved) {
    const bool diagnosed = failed_folder && search_was_cut_short(result);
    if (diagnosed) write_failed_search(summary(solution), problem_.decomposition(), *failed_folder, render);
    return Failure{no_plan_line(planner_, result), diagnosed};
  }
  // The run's deadline came while the plan the search found was replayed: it is not known to be valid.
  if (!solution.replay->cut_short.empty()) {
    return Failure{"no plan found (" + solution.replay->cut_short + "): the run's time ran out while replaying the plan "
                   "the search found, so it is not validated"};
  }
  // The search and the replay disagree: a bug, never a result.
  if (!solution.replay->validated()) return Failure{"BUG: the plan failed validation on replay: " + solution.replay->failure};
  return std::nullopt;
}

RunSummary PlanningRun::summary(const planning::ValidatedPlan& solution) const {
  return {problem_.world(),
          settings_,
          problem_.reasoning(),
          problem_.as_written(),
          planner_,
          solution.result,
          solution.replay ? &*solution.replay : nullptr,
          solution.improvement ? &*solution.improvement : nullptr};
}

PlanCostFigures PlanningRun::plan_cost(const planning::ValidatedPlan& solution) const {
  const scenario::World& world = problem_.world();
  PlanCostFigures figures;
  const scenario::PlanCost& cost = settings_.improvement.cost;
  figures.value = planning::cost_of(cost, planning::measure(world, solution.result.plan, *solution.replay));
  try {
    const double bound = planning::plan_cost_bound(world, problem_.as_written(), cost, deadline_);
    if (std::isfinite(bound)) figures.bound = bound;
  } catch (const base::DeadlineReached& reached) {
    if (reached.interrupted()) throw;  // the time limit leaves the bound unset, Ctrl-C ends the run
    figures.bound_cut_short = true;
  }
  return figures;
}

}  // namespace physltl::app
