#pragma once
// What every planner takes and gives (planner.h): the options of one search and its result.

#include "physltl/decomposition/decomposition.h"
#include "physltl/knowledge/abstract_knowledge.h"
#include "physltl/planning/plan.h"
#include "physltl/planning/planner_kind.h"
#include "physltl/planning/route_choice.h"
#include "physltl/planning/task.h"

#include <atomic>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace physltl::planning {

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
  // The knowledge planner and the baseline stop with "budget" after this many propagations (0: no bound),
  // checked between batches, so a seed gives the same plan or the same failure on any machine and load
  // (execution's replanning, docs/robustness.md). OMPL's planners do not take it.
  long long max_propagations = 0;
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
  std::string stop_reason;  // "solved", "time limit", "budget", "interrupted", "tree full", "no lead", "no solution"
  Plan plan;
  std::vector<TreeEdge> tree;
  PlannerStats stats;
  // How the planner was configured, for bench.json and the OMPL log (name, value as text).
  std::vector<std::pair<std::string, std::string>> settings;
};

}  // namespace physltl::planning
