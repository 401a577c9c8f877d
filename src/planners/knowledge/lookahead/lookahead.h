#pragma once
// The look-ahead as a run prepares it (push_plan.h): whether it applies, the lattice, and the push order
// found from the World's start, which the knowledge planner's tree follows (tree/push_plan_lead.h).

#include "push_lattice.h"
#include "push_search.h"
#include "push_plan.h"
#include "physltl/planning/task.h"

#include <optional>
#include <vector>

namespace physltl::planners::knowledge::lookahead {

struct Lookahead {
  PushPlan plan;
  std::optional<PushLattice> lattice;  // where the rule applies
  int stage = 0;                       // the stage the pushes start from
  std::vector<int> start_cells;
  std::vector<PushStep> steps;         // one lattice step each; plan.pushes joins them into runs
};

// `stages`: of `task`. `max_arrangements`: the discrete search's budget (push_search.h). Throws
// DeadlineReached.
Lookahead look_ahead(const scenario::World& world, const physltl::knowledge::AbstractKnowledge& knowledge, const planning::TaskAutomaton& task,
                     const planning::StageGraph& stages, const base::Deadline& deadline = {}, long long max_arrangements = kMaxArrangements);

// Steps of one body in one direction after each other, as one push each.
std::vector<PlannedPush> runs_of(const PushLattice& lattice, const std::vector<PushStep>& steps);

}  // namespace physltl::planners::knowledge::lookahead
