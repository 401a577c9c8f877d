#include "planning_run.h"

#include "common/bad_input.h"
#include "common/stop_signal.h"
#include "run/planner_names.h"
#include "run/scenario_settings.h"
#include "run/cost_args.h"
#include "run/uncertainty_args.h"
#include "views/failed_search.h"
#include "physltl/planning/path_lower_bound.h"
#include "physltl/planning/validation/improve.h"

#include <cmath>

namespace physltl::app {

scenario::World load_world(const std::string& path, const std::vector<std::string>& settings, const WorldOverrides& overrides) {
  scenario::World world = load_with_settings(path, settings);
  if (overrides.seed) world.planner.seed = *overrides.seed;
  if (overrides.time_limit) world.planner.time_limit = *overrides.time_limit;
  if (overrides.uncertainty) world.uncertainty = override_uncertainty(world.uncertainty, *overrides.uncertainty);
  if (overrides.cost) world.planner.cost = cost_from_flag(*overrides.cost);
  if (overrides.view) world.render.view = *overrides.view;
  if (overrides.improve_margin) world.planner.improve_margin = *overrides.improve_margin;
  return world;
}

PlanningRun::PlanningRun(const scenario::World& world, const planning::PlannerEntry& planner)
    : deadline_(base::Deadline::in(world.planner.time_limit, &stop_flag())), problem_(world), planner_(planner) {}

planning::PlannerOptions PlanningRun::options() const {
  planning::PlannerOptions options = planning::options_for(problem_.world());
  options.deadline = deadline_;
  return options;
}

void PlanningRun::require_plannable(planning::Needs needs) const {
  if (!problem_.feasible()) throw InfeasibleTask(problem_.reasoning().task.infeasibility());
  if (const auto why = registry().refusal(planner_, problem_.search_task(planner_), needs)) throw BadInput(*why);
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
  figures.value = planning::cost_of(world.planner.cost, planning::measure(world, solution.result.plan, *solution.replay));
  try {
    const double bound = planning::plan_cost_bound(world, problem_.as_written(), world.planner.cost, deadline_);
    if (std::isfinite(bound)) figures.bound = bound;
  } catch (const base::DeadlineReached& reached) {
    if (reached.interrupted()) throw;  // the time limit leaves the bound unset, Ctrl-C ends the run
    figures.bound_cut_short = true;
  }
  return figures;
}

}  // namespace physltl::app
