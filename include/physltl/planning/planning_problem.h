#pragma once
// One World's planning problem, made in one place and solved any number of times (per planner, seed and
// thread count) by run, bench and execute alike: the reasoning about it, the task as the planners search
// it and as written, the decomposition and the knowledge planner's route choice. Only a plan that replay
// validated counts as solved.

#include "physltl/decomposition/decomposition.h"
#include "physltl/knowledge/reasoning.h"
#include "physltl/planners/knowledge/push_plan.h"
#include "physltl/planning/registry.h"
#include "physltl/planners/knowledge/route_choice.h"
#include "physltl/planning/task.h"
#include "physltl/planning/validation/validated_plan.h"

#include <chrono>
#include <memory>
#include <optional>
#include <string>

namespace physltl::planning {

class PlanningProblem {
 public:
  // Reasons about `world`, which must outlive this object; a feasible task is also prepared for the
  // planners. `started`: when the run began, for preparation_s().
  explicit PlanningProblem(const scenario::World& world,
                           std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now());

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
  const RouteChoice& routes() const { return prepared_->routes; }
  // The knowledge planner's look-ahead: whether it applies and the push order it follows.
  const PushPlan& lookahead() const;
  // Seconds the reasoning, the decomposition and the route choice took: once per World and task.
  double preparation_s() const { return preparation_s_; }
  // Why `planner` cannot take this task (and `needs`); nothing when it can.
  std::optional<std::string> refusal(const PlannerEntry& planner, Needs needs = {}) const;
  // What `planner` searches.
  Problem for_planner(const PlannerEntry& planner) const;

 private:
  struct Prepared {
    TaskAutomaton simplified;
    TaskAutomaton as_written;
    decomposition::Decomposition decomposition;
    RouteChoice routes;
    std::shared_ptr<const lookahead::Lookahead> lookahead;
  };
  static std::optional<Prepared> prepare(const scenario::World& world, const knowledge::Reasoning& reasoning);

  const scenario::World& world_;
  knowledge::Reasoning reasoning_;
  std::optional<Prepared> prepared_;
  double preparation_s_ = 0.0;
};

// Plans with `planner` (options.threads threads growing one search) and validates the plan by replay.
ValidatedPlan solve(const PlanningProblem& problem, const PlannerEntry& planner, const PlannerOptions& options);

}  // namespace physltl::planning
