#pragma once
// One World's planning problem, made in one place and solved any number of times (per planner, seed and
// thread count) by run, bench and execute alike: the reasoning about it, the task as the planners search
// it and as written, the decomposition, and what each planner prepared of it (its entry's prepare, run
// the first time the planner is asked for and kept). Only a plan that replay validated counts as solved.

#include "physltl/decomposition/decomposition.h"
#include "physltl/knowledge/reasoning.h"
#include "physltl/planning/registry.h"
#include "physltl/planning/task.h"
#include "physltl/planning/validation/validated_plan.h"

#include <chrono>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

namespace physltl::planning {

class PlanningProblem {
 public:
  // Reasons about `world`, which must outlive this object; a feasible task is also prepared for the
  // planners, for runs of `time_limit_s` (Problem::time_limit_s). The reasoning stops judging at
  // `deadline` (knowledge::reason_about): give the run's, so that a reasoning past it concludes nothing
  // more and the planner's preparation, which asks the deadline first, ends the run. `started`:
  // when the run began, for preparation_s().
  PlanningProblem(const scenario::World& world, double time_limit_s, const base::Deadline& deadline = {},
                  std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now());
  // For runs of the time limit the World's planner { } gives.
  explicit PlanningProblem(const scenario::World& world) : PlanningProblem(world, world.planner.time_limit) {}

  const scenario::World& world() const { return world_; }
  const knowledge::Reasoning& reasoning() const { return reasoning_; }
  bool feasible() const { return prepared_.has_value(); }

  // The rest only for a feasible task.
  // The automaton `planner` searches: the simplified formula's for a planner that uses knowledge, the
  // formula as written otherwise (the paper's simple planner has no reasoning).
  const TaskAutomaton& search_task(const PlannerEntry& planner) const;
  // The formula as written, which every replay checks.
  const TaskAutomaton& as_written() const { return prepared_->as_written; }
  const decomposition::Decomposition& decomposition() const { return prepared_->decomposition; }
  // What `planner` prepared of this problem (null when it prepares nothing), made on the first call;
  // throws DeadlineReached when `options.deadline` comes first (nothing kept: a later call prepares
  // again). A preview's preparation is made again when a full one is asked for.
  const PlannerData* preparation(const PlannerEntry& planner, const PreparationOptions& options = {}) const;
  // Seconds the reasoning and the decomposition took, once per World and task, and what `planner`
  // prepared of them; without a planner, what every planner prepared so far.
  double preparation_s(const PlannerEntry& planner) const;
  double preparation_s() const;
  // What `planner` searches.
  Problem for_planner(const PlannerEntry& planner) const;

 private:
  struct Prepared {
    TaskAutomaton simplified;
    TaskAutomaton as_written;
    decomposition::Decomposition decomposition;
  };
  struct PlannerPreparation {
    std::shared_ptr<const PlannerData> data;
    double seconds = 0.0;
    bool preview = false;
  };
  static std::optional<Prepared> prepare(const scenario::World& world, const knowledge::Reasoning& reasoning);

  const scenario::World& world_;
  double time_limit_s_;
  knowledge::Reasoning reasoning_;
  std::optional<Prepared> prepared_;
  double preparation_s_ = 0.0;
  mutable std::mutex planners_mutex_;
  mutable std::map<const PlannerEntry*, PlannerPreparation> planners_;
};

// Plans with `planner` (options.threads threads growing one search), validates the plan by replay and
// spends `improvement` lowering its cost; the planner's preparation, when this is its first run, is within
// options.deadline too (a result with stop reason "time limit" or "interrupted" when it comes first).
ValidatedPlan solve(const PlanningProblem& problem, const PlannerEntry& planner, const PlannerOptions& options,
                    const ImprovementSettings& improvement = {});

}  // namespace physltl::planning
