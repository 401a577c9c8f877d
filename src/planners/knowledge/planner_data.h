#pragma once
// What the knowledge planner and the baseline (the same tree search without knowledge) keep of their own
// (planning/planner_entry.h): what the knowledge planner prepares once per problem, the rules of its own
// that refuse a step, and what a search reports beside its plan. Shown by account.cpp.

#include "lookahead/lookahead.h"
#include "lookahead/push_plan.h"
#include "route_choice.h"

#include "physltl/planning/planner_entry.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace physltl::planners::knowledge {

// Prepared once per problem (PlannerEntry::prepare): going round or pushing through, per stage, and the
// look-ahead's push order.
struct KnowledgePreparation : planning::PlannerData {
  std::shared_ptr<const planning::StageGraph> stages;  // of the task the planner searches
  RouteChoice routes;
  lookahead::Lookahead lookahead;
  bool task_names_bodies = false;
};

// The knowledge planner's own rules (PlannerEntry::own_refusals, Refusals::own) beside the semantic ones:
// its heuristics, which a stalled search widens past (docs/planner.md, "Cuts and biases").
enum class OwnRefusal {
  kRouteChoiceCut,  // the robot touched a body in a stage whose lead goes round the bodies
  kDroppedNode,     // a node left out after its expansions kept failing at their first step
};
inline const std::vector<std::string> kOwnRefusalNames = {"route_choice_cut", "dropped_node"};
inline constexpr int own_rule(OwnRefusal rule) { return static_cast<int>(rule); }

// Where the tree search stood when it stopped without a plan (failed/report.json, docs/report.md).
struct SearchEnd {
  struct Stage {
    int automaton_state = 0;
    std::vector<std::string> facts;  // the named bodies' places that matter there: "crate@dock"
    int distance = -1;               // stage moves to acceptance
  };
  struct StageNodes {
    Stage stage;
    long long nodes = 0;    // grown into it, dropped ones included
    long long dropped = 0;  // left out after failing expansions (OwnRefusal::kDroppedNode)
  };
  struct LeadStep {
    geometry::Vec2 point = geometry::Vec2::Zero();  // the centroid of the lead's triangle
    int automaton_state = 0;
  };
  Stage frontier;  // the stage closest to acceptance any node reached
  // The lead the last expansions followed, from the node it started at; empty when the object lead led.
  std::vector<LeadStep> lead;
  std::string body_move;  // the object lead's move when it led: "crate to dock", "crate out of dock"
  std::vector<StageNodes> nodes_per_stage;  // stages holding a node, in the order the tree reached them
  // The push of the look-ahead's order under way at the node furthest along it: the one the physics did not
  // carry out (index from 1, of `order_pushes`, as the order stood after its last replanning); 0 when the
  // search followed no order or got no node onto it.
  int order_push = 0;
  int order_pushes = 0;
  PlannedPush unfinished_push;  // that push, when order_push > 0
  long long expansions_since_progress = 0;  // since a node last got closer to acceptance
  bool widened = false;  // the frontier had stalled: some expansions grew as the baseline grows
};

// What a search reports beside its plan (PlanResult::own).
struct SearchReport : planning::PlannerData {
  // The look-ahead's push order from the start that the search followed, and how many times it planned
  // the order again from where the physics left the bodies; none when it followed none.
  std::optional<PushPlan> lookahead;
  int lookahead_replans = 0;
  long long primitive_controls = 0;  // controls the push primitives propagated (of the run's propagations)
  std::optional<SearchEnd> end;  // when it stopped without a plan
};

// The planner's own data in the program's forms (PlannerEntry::account).
planning::PlannerAccount knowledge_account(const planning::PlannerData& data, const scenario::World& world);

}  // namespace physltl::planners::knowledge
