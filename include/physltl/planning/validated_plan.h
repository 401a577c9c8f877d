#pragma once
// A search and the check of its result: the plan is replayed in a fresh world and its region trace read
// by the formula as written. Only a plan that replay validated counts as solved.

#include "physltl/planning/planner.h"
#include "physltl/planning/replay.h"

#include <cstdint>

#include <optional>

namespace physltl::planning {

// What a validated plan needs: the search's inputs and the formula replay checks against.
struct Problem {
  const scenario::World& world;
  const TaskAutomaton& task;     // what the search aims at (the simplified formula for the knowledge planner)
  const TaskAutomaton& formula;  // the task as written, which a plan's replay must satisfy
  const knowledge::AbstractKnowledge& knowledge;
  const decomposition::Decomposition& decomposition;
};

// What improving a plan did (improve.h).
struct PlanMeasures {
  double duration_s = 0.0;
  int pushes = 0;
  int bodies_moved = 0;
  double path_length_m = 0.0;  // the robot's centre, step by step
};

struct Improvement {
  int candidates = 0;  // tried
  int accepted = 0;    // each better than the plan before
  PlanMeasures first;
  PlanMeasures improved;
  double time_s = 0.0;
};

struct ValidatedPlan {
  PlanResult result;             // result.plan is the improved plan when improvement ran
  std::optional<Replay> replay;  // of result.plan, when the search solved
  std::optional<Improvement> improvement;  // when options.improve > 0 and the first plan validated

  // A search that solved but whose plan failed replay is a bug, kept so it can be reported.
  bool solved() const { return replay.has_value() && replay->validated(); }
};

ValidatedPlan plan_and_validate(const Problem& problem, const PlannerOptions& options);

}  // namespace physltl::planning
