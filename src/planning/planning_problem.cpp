#include "physltl/planning/planning_problem.h"

namespace physltl::planning {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

PlanningProblem::PlanningProblem(const scenario::World& world, double time_limit_s, const base::Deadline& deadline,
                                 std::chrono::steady_clock::time_point started)
    : world_(world),
      time_limit_s_(time_limit_s),
      reasoning_(knowledge::reason_about(world, deadline)),
      prepared_(prepare(world, reasoning_)),
      preparation_s_(seconds_since(started)) {}

std::optional<PlanningProblem::Prepared> PlanningProblem::prepare(const scenario::World& world,
                                                                  const knowledge::Reasoning& reasoning) {
  if (!reasoning.feasible()) return std::nullopt;
  TaskAutomaton simplified = TaskAutomaton::make(*reasoning.simplified_formula(), *reasoning.task.dfa, world);
  TaskAutomaton as_written = TaskAutomaton::make(reasoning.task.input, world);
  decomposition::Decomposition decomposition = decomposition::Decomposition::build(world);
  return Prepared{std::move(simplified), std::move(as_written), std::move(decomposition)};
}

const TaskAutomaton& PlanningProblem::search_task(const PlannerEntry& planner) const {
  return planner.uses_knowledge ? prepared_->simplified : prepared_->as_written;
}

const PlannerData* PlanningProblem::preparation(const PlannerEntry& planner, const PreparationOptions& options) const {
  const std::lock_guard lock(planners_mutex_);
  auto known = planners_.find(&planner);
  if (known == planners_.end() || (known->second.preview && !options.preview)) {
    // A deadline already past starts no work: a run whose preparation it cut short asks again for the
    // search, and a preparation's first steps (a task's stage graph) check no deadline for a second.
    options.deadline.check();
    const auto started = std::chrono::steady_clock::now();
    PlannerPreparation made;
    if (planner.prepare) made.data = planner.prepare(for_planner(planner), options);
    made.seconds = seconds_since(started);
    made.preview = options.preview;
    known = planners_.insert_or_assign(&planner, std::move(made)).first;
  }
  return known->second.data.get();
}

double PlanningProblem::preparation_s(const PlannerEntry& planner) const {
  preparation(planner);
  const std::lock_guard lock(planners_mutex_);
  return preparation_s_ + planners_.at(&planner).seconds;
}

double PlanningProblem::preparation_s() const {
  const std::lock_guard lock(planners_mutex_);
  double seconds = preparation_s_;
  for (const auto& [planner, made] : planners_) seconds += made.seconds;
  return seconds;
}

Problem PlanningProblem::for_planner(const PlannerEntry& planner) const {
  return {world_, search_task(planner), as_written(), reasoning_.knowledge, decomposition(), time_limit_s_};
}

ValidatedPlan solve(const PlanningProblem& problem, const PlannerEntry& planner, const PlannerOptions& options,
                    const ImprovementSettings& improvement) {
  const PlannerData* prepared = nullptr;
  try {
    prepared = problem.preparation(planner, {options.deadline});
  } catch (const base::DeadlineReached& reached) {
    // Cut short before any search: no plan, for the reason the deadline gives.
    ValidatedPlan cut;
    cut.result.stop_reason = reached.interrupted() ? StopReason::kInterrupted : StopReason::kTimeLimit;
    return cut;
  }
  return plan_and_validate(problem.for_planner(planner), planner, prepared, options, improvement);
}

}  // namespace physltl::planning
