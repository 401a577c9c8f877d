#include "planning_job.h"

#include "physltl/ltl/parser.h"

namespace physltl::app {

PreparedRun::PreparedRun(const scenario::World& world, const Reasoning& reasoning,
                         std::chrono::steady_clock::time_point started)
    : world_(world),
      reasoning_(reasoning),
      simplified_(planning::TaskAutomaton::make(*reasoning.simplified_formula(), *reasoning.task.dfa, world)),
      as_written_(planning::TaskAutomaton::make(ltl::parse(world.task.formula), world)),
      decomposition_(decomposition::Decomposition::build(world)),
      routes_(planning::choose_routes(world, simplified_, decomposition_)),
      preparation_s_(std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count()) {}

const planning::TaskAutomaton& PreparedRun::search_task(planning::PlannerKind planner) const {
  return planner == planning::PlannerKind::kBaseline ? as_written_ : simplified_;
}

planning::ValidatedPlan solve(const PreparedRun& run, const SolveOptions& options) {
  planning::PlannerOptions planner;
  planner.planner = options.planner;
  planner.ompl_control_sampler = options.ompl_control_sampler;
  planner.seed = options.seed;
  planner.time_limit = options.time_limit;
  planner.stop = options.stop;
  planner.threads = options.threads;
  planner.improve = options.improve;
  planner.max_propagations = options.max_propagations;
  planner.routes = &run.routes();
  const planning::Problem problem{run.world(), run.search_task(options.planner), run.as_written(),
                                  run.reasoning().knowledge, run.decomposition()};
  return planning::plan_and_validate(problem, planner);
}

}  // namespace physltl::app
