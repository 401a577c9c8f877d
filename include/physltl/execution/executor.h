#pragma once
// Execution with monitoring and replanning: a plan runs step by step in an ExecutionWorld; when the robot,
// or a body the plan moves, is farther from its planned position than the tolerance, or the robot's offset
// from the plan would take it into a fixed body within half a second, the robot brakes to rest and the rest
// of the task is planned again from the state it observes, in the declared model (the executor never sees
// the truth, only states), with the task progressed over the letters executed so far (docs/robustness.md).

#include "physltl/execution/execution_world.h"
#include "physltl/planning/plan.h"
#include "physltl/planning/validation/replay.h"
#include "physltl/planning/task.h"
#include "physltl/scenario/state_trace.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace physltl::execution {

// A plan for the rest of the task from the model world `from_here` (its start is the observed state, its
// formula the remaining task), with its replay in that model; no plan when the search found none.
struct Replanned {
  std::optional<planning::Plan> plan;
  std::optional<planning::Replay> nominal;
  long long propagations = 0;
  double planning_s = 0.0;
  std::string stop_reason;
};
using Replanner = std::function<Replanned(const scenario::World& from_here)>;

struct ExecutionOptions {
  double tolerance_m = 0.15;  // how far the robot or a pushed body may be from where the plan has it
  int max_replans = 5;
  int max_braking_steps = 400;  // of the world's step_size: braking that takes longer gives up
};

struct Execution {
  std::vector<planning::Control> controls;  // as executed: the plans' controls, cut where they were left, and braking
  int replans = 0;
  std::vector<int> replan_steps;     // the physics step at which each replanning started
  std::vector<std::string> replan_results;  // each replanning's stop reason ("solved", "budget", ...)
  long long planning_propagations = 0;
  double planning_s = 0.0;           // wall time of the replanning, not simulated time
  int steps = 0;                     // physics steps executed
  std::string stopped;               // why execution ended before the task was done: "", "no plan", "task lost", "braking"
  scenario::StateTrace states;  // the observed state after each step, the initial one first; each body kept where it changed
};

// Runs `plan` (validated in `model`, whose replay is `nominal`; `formula` is the task as written) in any
// number of worlds; what monitoring it needs of the plan is computed once, here. All must outlive it.
class Executor {
 public:
  Executor(const scenario::World& model, const planning::TaskAutomaton& formula, const planning::Plan& plan,
           const planning::Replay& nominal, const ExecutionOptions& options);
  // One execution in `world`, which starts in the truth's initial state.
  Execution run(ExecutionWorld& world, const Replanner& replanner) const;

 private:
  const scenario::World& model_;
  const planning::TaskAutomaton& formula_;
  const planning::Plan& plan_;
  const planning::Replay& nominal_;
  std::vector<double> clearance_;  // the robot's from the fixed bodies at each step of `nominal`
  ExecutionOptions options_;
};

// The model world as it stands in `state`: the robot's start and every movable body where `state` has
// them, and `formula` as its task.
scenario::World world_from_state(const scenario::World& model, const scenario::EnvironmentState& state,
                                 const ltl::Formula& formula);

}  // namespace physltl::execution
