#pragma once
// Physics-based LTL planning (paper Algorithm 3): a Bhatia-style search over the product of a triangular
// decomposition and the task automaton, growing a tree of controls whose states come from the ODE
// propagator, with the knowledge layer's INFERENCE after every step and its rules as the validity check.
//
// Why not OMPL's LTLPlanner: it labels neither the start state nor the cells crossed within one
// propagation (a fast robot skips cells and reaches product states the graph does not expect), solve()
// runs once per planner, and OMPL's random generator is seeded process-wide, which defeats one seed per
// run and per thread. This loop keeps the same structure (lead, available regions, weights), tracks the
// automaton at every physics step, grows mostly from the lead's frontier, and lets several threads grow
// one tree without changing the plan (docs/planner.md).

#include "physltl/decomposition/decomposition.h"
#include "physltl/knowledge/abstract_knowledge.h"
#include "physltl/knowledge/validity.h"
#include "physltl/planning/plan.h"
#include "physltl/planning/task.h"

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

namespace physltl::planning {

enum class Guidance {
  kKnowledge,  // kappa-aware validity and control sampling (the paper's planner)
  kBaseline,   // the paper's "simple physics-based LTL planner": fixed-body contacts only, uniform controls
};

struct PlannerOptions {
  Guidance guidance = Guidance::kKnowledge;
  std::uint64_t seed = 1;
  double time_limit = 60.0;                     // s of wall-clock planning
  const std::atomic<bool>* stop = nullptr;      // set from elsewhere (Ctrl-C, another thread's success)
  std::size_t max_tree_nodes = 2'000'000;       // memory bound: ~0.5 KiB per node
  // Threads growing the one tree, each with its own ODE world. The plan does not depend on it: a seed
  // gives the same plan with any number of threads, only sooner.
  int threads = 1;
  // Candidates plan_and_validate spends shortening the first validated plan (improve.h); 0: none.
  int improve = 0;
};

struct PlannerStats {
  double planning_time_s = 0.0;
  long long propagations = 0;   // controls tried
  long long physics_steps = 0;  // ODE steps taken
  long long tree_nodes = 0;
  long long invalid_steps = 0;  // steps the validity checker refused
};

struct PlanResult {
  bool solved = false;
  std::string stop_reason;  // "solved", "time limit", "interrupted", "tree full", "no lead"
  Plan plan;
  std::vector<TreeEdge> tree;
  PlannerStats stats;
};

PlanResult plan(const scenario::World& world, const TaskAutomaton& task, const knowledge::AbstractKnowledge& knowledge,
                const decomposition::Decomposition& decomposition, const PlannerOptions& options);

knowledge::ValidityMode validity_mode(Guidance guidance);

}  // namespace physltl::planning
