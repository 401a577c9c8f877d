#pragma once
// Which planner searches, by name, and which tasks each can take. Ours, with or without the knowledge
// framework, or one of OMPL's on the same problem: the same physics, the same knowledge validity checker,
// the same decomposition and automaton (ompl_planner.cpp, docs/benchmarks.md).

#include "physltl/knowledge/validity.h"
#include "physltl/planning/task.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace physltl::planning {

enum class PlannerKind {
  kKnowledge,   // kappa-aware validity and control sampling (the paper's planner)
  kBaseline,    // the paper's "simple physics-based LTL planner": fixed-body contacts only, uniform controls
  kOmplLtl,     // OMPL's LTLPlanner (Bhatia et al.)
  kOmplRrt,     // OMPL's control planners, searching OMPL's product of the decomposition and the automaton
  kOmplKpiece,
  kOmplSst,
  kOmplPdst,
};

// "knowledge", "baseline", "ompl-ltl", "ompl-rrt", "ompl-kpiece", "ompl-sst", "ompl-pdst".
const char* planner_name(PlannerKind planner);
std::optional<PlannerKind> planner_from_name(std::string_view name);
const std::vector<PlannerKind>& all_planners();
bool is_ompl(PlannerKind planner);

// Why `planner` cannot plan `task`, in a sentence; nothing when it can. OMPL's product takes co-safe
// tasks (and co-safe with safety) about the robot's regions: not plans that must end at rest, nor tasks
// that name where bodies are.
std::optional<std::string> refusal(PlannerKind planner, const TaskAutomaton& task);

// The baseline checks contacts with fixed bodies only; every other planner checks kappa.
knowledge::ValidityMode validity_mode(PlannerKind planner);

}  // namespace physltl::planning
