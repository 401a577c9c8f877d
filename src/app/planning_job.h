#pragma once
// What the main job and `bench` share: a World and its Reasoning turned into the planner's inputs once,
// then solved any number of times (per planner, seed and thread count). Only a plan that replay validated
// counts as solved.

#include "physltl/decomposition/decomposition.h"
#include "physltl/planning/validated_plan.h"
#include "physltl/planning/route_choice.h"
#include "physltl/planning/task.h"
#include "reasoning.h"

#include <atomic>
#include <chrono>
#include <cstdint>

namespace physltl::app {

class PreparedRun {
 public:
  // Expects a feasible reasoning (reasoning.feasible()); both must outlive this object.
  PreparedRun(const scenario::World& world, const Reasoning& reasoning,
              std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now());

  const scenario::World& world() const { return world_; }
  const Reasoning& reasoning() const { return reasoning_; }
  // The automaton the search aims at: the simplified formula's for the knowledge planner and OMPL's
  // planners (all use the knowledge framework), the formula as written for the baseline (the paper's
  // simple planner has no reasoning).
  const planning::TaskAutomaton& search_task(planning::PlannerKind planner) const;
  // The formula as written, which every replay checks.
  const planning::TaskAutomaton& as_written() const { return as_written_; }
  const decomposition::Decomposition& decomposition() const { return decomposition_; }
  // The knowledge planner's route choice for its search task, prepared once (route_choice.h).
  const planning::RouteChoice& routes() const { return routes_; }
  // Seconds the decomposition and the route choice took: done once per world and task, not per run.
  double preparation_s() const { return preparation_s_; }

 private:
  const scenario::World& world_;
  const Reasoning& reasoning_;
  planning::TaskAutomaton simplified_;
  planning::TaskAutomaton as_written_;
  decomposition::Decomposition decomposition_;
  planning::RouteChoice routes_;
  double preparation_s_ = 0.0;
};

struct SolveOptions {
  planning::PlannerKind planner = planning::PlannerKind::kKnowledge;
  planning::OmplControlSampler ompl_control_sampler = planning::OmplControlSampler::kOmpl;
  std::uint64_t seed = 1;
  double time_limit = 60.0;
  int threads = 1;
  int improve = 0;  // candidates spent shortening the first validated plan
  long long max_propagations = 0;  // 0: none; the knowledge planner and the baseline stop at it ("budget")
  const std::atomic<bool>* stop = nullptr;  // Ctrl-C
};

// Plans with options.threads threads growing one tree and validates the plan by replay.
planning::ValidatedPlan solve(const PreparedRun& run, const SolveOptions& options);

}  // namespace physltl::app
