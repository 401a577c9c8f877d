#pragma once
// The proof of a plan: run its controls again from the start in a fresh physics world and check what
// happens, independently of the search that produced it.

#include "physltl/knowledge/abstract_knowledge.h"
#include "physltl/knowledge/validity.h"
#include "physltl/planning/plan.h"
#include "physltl/planning/task.h"

#include <string>
#include <vector>

namespace physltl::planning {

struct Replay {
  // One entry per physics step, the initial state first.
  std::vector<scenario::EnvironmentState> states;
  std::vector<int> region_trace;     // region index at each state, -1 outside every region
  std::vector<int> automaton_trace;  // state of the formula's automaton after reading each region
  std::vector<bool> pushing;         // the robot touched a movable body during the step into this state
  int pushes = 0;                    // controls during which the robot touched a movable body

  bool reproduces_plan = false;  // every state after a control equals the planned one, bit for bit
  bool valid = false;            // every step passes the validity rules of the mode it was planned in
  bool accepted = false;         // the region trace is a good prefix of the formula
  std::string failure;           // why not, for people; empty when validated
  bool validated() const { return reproduces_plan && valid && accepted; }
};

// Replays `plan` and checks it against `formula` (the task as written, not the simplified one the search
// used) and against the validity rules of `mode`.
Replay replay(const scenario::World& world, const Plan& plan, const TaskAutomaton& formula,
              const knowledge::AbstractKnowledge& knowledge, knowledge::ValidityMode mode);

// Region names along the trace ("p0" outside every region), as plan.json stores them.
std::vector<std::string> region_names(const scenario::World& world, const std::vector<int>& region_trace);

}  // namespace physltl::planning
