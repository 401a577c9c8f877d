#include "physltl/planning/planning_problem.h"

#include "physltl/ltl/parser.h"

namespace physltl::planning {

PlanningProblem::PlanningProblem(const scenario::World& world, std::chrono::steady_clock::time_point started)
    : world_(world),
      reasoning_(knowledge::reason_about(world)),
      prepared_(prepare(world, reasoning_)),
      preparation_s_(std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count()) {}

std::optional<PlanningProblem::Prepared> PlanningProblem::prepare(const scenario::World& world,
                                                                  const knowledge::Reasoning& reasoning) {
  if (!reasoning.feasible()) return std::nullopt;
  TaskAutomaton simplified = TaskAutomaton::make(*reasoning.simplified_formula(), *reasoning.task.dfa, world);
  TaskAutomaton as_written = TaskAutomaton::make(ltl::parse(world.task.formula), world);
  decomposition::Decomposition decomposition = decomposition::Decomposition::build(world);
  RouteChoice routes = choose_routes(world, simplified, decomposition);
  auto ahead = prepare_lookahead(world, reasoning.knowledge, simplified);
  return Prepared{std::move(simplified), std::move(as_written), std::move(decomposition), std::move(routes), std::move(ahead)};
}

const TaskAutomaton& PlanningProblem::search_task(const PlannerEntry& planner) const {
  return planner.uses_knowledge ? prepared_->simplified : prepared_->as_written;
}

std::optional<std::string> PlanningProblem::refusal(const PlannerEntry& planner, Needs needs) const {
  return PlannerRegistry::instance().refusal(planner, search_task(planner), needs);
}

const PushPlan& PlanningProblem::lookahead() const { return push_plan_of(*prepared_->lookahead); }

Problem PlanningProblem::for_planner(const PlannerEntry& planner) const {
  return {world_, search_task(planner), as_written(), reasoning_.knowledge, decomposition(), &routes(),
          planner.uses_knowledge ? prepared_->lookahead.get() : nullptr};
}

ValidatedPlan solve(const PlanningProblem& problem, const PlannerEntry& planner, const PlannerOptions& options) {
  return plan_and_validate(problem.for_planner(planner), planner, options);
}

}  // namespace physltl::planning
