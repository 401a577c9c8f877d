#pragma once
// What every planner takes and gives (registry.h): the options of one search and its result.

#include "physltl/decomposition/decomposition.h"
#include "physltl/knowledge/abstract_knowledge.h"
#include "physltl/planners/knowledge/push_plan.h"
#include "physltl/planning/plan.h"
#include "physltl/planning/refusal.h"
#include "physltl/planning/task.h"

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace physltl::planning {

// How OMPL's planners sample controls: with OMPL's uniform sampler, or with ours (the knowledge
// planner's, aiming at the state RRT and PDST grow towards, or at a random point for KPIECE1 and
// LTLPlanner; SST samples without a state, so uniformly either way).
enum class OmplControlSampler { kOmpl, kOurs };

struct PlannerOptions {
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
  // Refused steps by rule, and our tree search's dropped nodes (refusal.h).
  Refusals refused;
  // The knowledge planner's look-ahead (lookahead/push_plan.h): push orders planned again from where the
  // physics left the bodies off the order.
  int lookahead_replans = 0;
};

// Where our tree search stood when it stopped without a plan (failed/report.json, docs/report.md).
struct SearchEnd {
  struct Stage {
    int automaton_state = 0;
    std::vector<std::string> facts;  // the named bodies' places that matter there: "crate@dock"
    int distance = -1;               // stage moves to acceptance
  };
  struct StageNodes {
    Stage stage;
    long long nodes = 0;    // grown into it, dropped ones included
    long long dropped = 0;  // left out after failing expansions (refusal.h)
  };
  struct LeadStep {
    Vec2 point = Vec2::Zero();  // the centroid of the lead's triangle
    int automaton_state = 0;
  };
  bool known = false;  // false: the planner does not say (OMPL's)
  Stage frontier;      // the stage closest to acceptance any node reached
  // The lead the last expansions followed, from the node it started at; empty when the object lead led.
  std::vector<LeadStep> lead;
  std::string body_move;  // the object lead's move when it led: "crate to dock", "crate out of dock"
  std::vector<StageNodes> nodes_per_stage;  // stages holding a node, in the order the tree reached them
  long long expansions_since_progress = 0;  // since a node last got closer to acceptance
  bool widened = false;  // the frontier had stalled: some expansions grew as the baseline grows
};

struct PlanResult {
  bool solved = false;
  std::string stop_reason;  // "solved", "time limit", "budget", "interrupted", "tree full", "no lead", "no solution"
  Plan plan;
  std::vector<TreeEdge> tree;
  PlannerStats stats;
  SearchEnd end;  // filled when not solved
  // The look-ahead's push order from the start that the knowledge planner followed (stats count the
  // orders planned again on the way); none when it followed none.
  std::optional<PushPlan> lookahead;
  // How the planner was configured, for bench.json and the OMPL log (name, value as text).
  std::vector<std::pair<std::string, std::string>> settings;
};

}  // namespace physltl::planning
