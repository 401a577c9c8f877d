#pragma once
// Our planners, knowledge and baseline: the product-graph tree search of docs/planner.md.
//
// Why our own loop and not OMPL's LTLPlanner (which runs beside it as a peer): LTLPlanner explores each
// lead for a wall-clock time, so a seed does not give one plan, and it needs guards for its unlabelled
// start and for steps that cross a thin triangle. Our loop keeps the same structure (lead, available
// regions, weights), tracks the automaton at every physics step, grows mostly from the lead's frontier,
// and lets several threads grow one tree without changing the plan (docs/planner.md); measured beside
// OMPL's planners in docs/benchmarks.md.

#include "planner_data.h"

#include "physltl/planning/planner_entry.h"
#include "physltl/planning/planner_options.h"
#include "physltl/planning/problem.h"

#include <string>

namespace physltl::planners::knowledge {

enum class TreeSearchMode {
  kKnowledge,  // kappa-aware validity, the route choice and its escape (the paper's planner)
  kBaseline,   // fixed-body contacts only, uniform controls (the paper's simple planner)
};

// The knowledge planner's parameter `push-primitives`: "on" (the default), the look-ahead's order is first
// carried out by closed-loop push primitives; "off", by sampled controls alone (for comparing the two).
const planning::PlannerParameter& push_primitives_parameter();

// `prepared`: the knowledge planner's route choice and look-ahead; without it, the knowledge search chooses
// its routes itself and follows no push order.
planning::PlanResult plan_with_tree_search(const planning::Problem& problem, const KnowledgePreparation* prepared, const planning::PlannerOptions& options,
                                 TreeSearchMode mode);

}  // namespace physltl::planners::knowledge
