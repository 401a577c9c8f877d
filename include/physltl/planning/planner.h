#pragma once
// Physics-based LTL planning (paper Algorithm 3): a Bhatia-style search over the product of a triangular
// decomposition and the task automaton, growing a tree of controls whose states come from the ODE
// propagator, with the knowledge layer's INFERENCE after every step and its rules as the validity check.
//
// Why our own loop and not OMPL's LTLPlanner (which runs beside it as a peer, ompl_planner.h): LTLPlanner
// explores each lead for a wall-clock time, so a seed does not give one plan, and it needs guards for
// its unlabelled start and for steps that cross a thin triangle. This loop keeps the same structure
// (lead, available regions, weights), tracks the automaton at every physics step, grows mostly from the
// lead's frontier, and lets several threads grow one tree without changing the plan (docs/planner.md);
// measured beside OMPL's planners in docs/benchmarks.md.

#include "physltl/decomposition/decomposition.h"
#include "physltl/knowledge/abstract_knowledge.h"
#include "physltl/knowledge/validity.h"
#include "physltl/planning/plan.h"
#include "physltl/planning/route_choice.h"
#include "physltl/planning/task.h"

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace physltl::planning {

// Which planner searches. Ours, with or without the knowledge framework, or one of OMPL's on the same
// problem: the same physics, the same knowledge validity checker, the same decomposition and automaton
// (ompl_planner.cpp, docs/benchmarks.md).
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

// How OMPL's planners sample controls: with OMPL's uniform sampler, or with ours (the knowledge
// planner's, aiming at the state RRT and PDST grow towards, or at a random point for KPIECE1 and
// LTLPlanner; SST samples without a state, so uniformly either way).
enum class OmplControlSampler { kOmpl, kOurs };

struct PlannerOptions {
  PlannerKind planner = PlannerKind::kKnowledge;
  OmplControlSampler ompl_control_sampler = OmplControlSampler::kOmpl;
  std::uint64_t seed = 1;
  double time_limit = 60.0;                     // s of wall-clock planning
  const std::atomic<bool>* stop = nullptr;      // set from elsewhere (Ctrl-C, another thread's success)
  std::size_t max_tree_nodes = 2'000'000;       // memory bound: ~0.5 KiB per node
  // Threads growing the one tree, each with its own ODE world. The plan does not depend on it: a seed
  // gives the same plan with any number of threads, only sooner.
  int threads = 1;
  // Candidates plan_and_validate spends shortening the first validated plan (improve.h); 0: none.
  int improve = 0;
  // The knowledge planner's choice of going round or pushing through (route_choice.h), prepared for the
  // task once; chosen by the search itself when not given.
  const RouteChoice* routes = nullptr;
};

struct PlannerStats {
  double planning_time_s = 0.0;
  long long propagations = 0;   // controls tried
  long long physics_steps = 0;  // ODE steps taken
  long long tree_nodes = 0;
  long long invalid_steps = 0;  // steps the validity checker refused
  // OMPL's planners: steps refused because the robot crossed into a triangle that is not a neighbour of
  // the one it left, which OMPL's product graph cannot follow (docs/benchmarks.md).
  long long cell_skips_refused = 0;
};

struct PlanResult {
  bool solved = false;
  std::string stop_reason;  // "solved", "time limit", "interrupted", "tree full", "no lead", "no solution"
  Plan plan;
  std::vector<TreeEdge> tree;
  PlannerStats stats;
  // How the planner was configured, for bench.json and the OMPL log (name, value as text).
  std::vector<std::pair<std::string, std::string>> settings;
};

PlanResult plan(const scenario::World& world, const TaskAutomaton& task, const knowledge::AbstractKnowledge& knowledge,
                const decomposition::Decomposition& decomposition, const PlannerOptions& options);

// Why `planner` cannot plan `task`, in a sentence; nothing when it can. OMPL's product takes co-safe
// tasks (and co-safe with safety) about the robot's regions: not plans that must end at rest, nor tasks
// that name where bodies are.
std::optional<std::string> refusal(PlannerKind planner, const TaskAutomaton& task);

// The baseline checks contacts with fixed bodies only; every other planner checks kappa.
knowledge::ValidityMode validity_mode(PlannerKind planner);

}  // namespace physltl::planning
