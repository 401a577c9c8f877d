#pragma once
// One planner as the program knows it (registry.h): its name, what it can take, the values it takes by
// name, what it prepares once per problem, its search, and how its own data is shown. The core reads
// none of a planner's own data: a planner keeps it in a PlannerData of its own and shows it through its
// entry's `account`, as OMPL keeps a planner's specs, parameters and setup() in the planner's own class.

#include "physltl/planning/planner_options.h"
#include "physltl/planning/problem.h"
#include "physltl/scenario/world.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace physltl::planning {

// A kind of task or request a planner may be unable to take, with the reason in words when it cannot.
struct Capability {
  bool can = true;
  std::string because;  // why not, when !can: "OMPL's product graph labels each triangle with ..."
};

struct Capabilities {
  Capability object_tasks;          // tasks that name where bodies are (BODY@REGION)
  Capability tasks_ending_at_rest;  // tasks only a plan that ends at rest satisfies
  Capability propagation_budget;    // stops at PlannerOptions::max_propagations ("budget"): execute's replanning
  bool threads = false;             // several threads grow one search (bench --threads K measures each K)
};

// What a caller asks of a planner beyond the task.
struct Needs {
  bool propagation_budget = false;
};

// A value a planner takes by name, as OMPL's declareParam: `--NAME VALUE` on the command lines of the
// commands that run the planner, and NAME (dashes as underscores) in a campaign's manifest.
struct PlannerParameter {
  std::string name;                  // "ompl-sampler"
  std::string help;                  // one line for --help
  std::vector<std::string> choices;  // the values it takes; the first is the default
  // What a value means for a benchmark's reader, one line under bench's table; empty for none (the default).
  std::function<std::string(const std::string& value)> note;

  const std::string& default_value() const { return choices.front(); }
};

// How far a planner's preparation goes. A preview (`check`) is not followed by a search: it must stay
// quick and say the same on any machine, so a planner bounds its work there by budgets of its own, in
// units of work rather than seconds, smaller than a run's, and its account says when one stopped it.
struct PreparationOptions {
  base::Deadline deadline{};
  bool preview = false;
};

// What a planner keeps of its own, about a problem (what it prepared) or a search (what it reports).
class PlannerData {
 public:
  virtual ~PlannerData() = default;
};

// A planner's own data in the forms the program shows. JSON keys are among the entry's declared ones.
struct PlannerAccount {
  nlohmann::ordered_json report = nlohmann::ordered_json::object();     // report.json and `check --json`
  nlohmann::ordered_json diagnosis = nlohmann::ordered_json::object();  // failed/report.json, a search without a plan
  std::vector<std::string> lines;    // the console, before a search and in `check`: "lookahead  2 pushes: ..."
  std::vector<std::string> details;  // `check` alone: what says the planner's guidance is off
  // Moves of bodies the planner intends, in order, drawn as arrows on tree.png and the video's frames.
  struct Move {
    Vec2 from = Vec2::Zero();
    Vec2 to = Vec2::Zero();
    Vec2 direction = Vec2::UnitX();  // unit
    int body = -1;                   // the World::movable_bodies index of the body moved; -1: not said
  };
  std::vector<Move> moves;
  std::string moves_legend;  // the legend's line for them
};

struct PlannerEntry {
  std::string name;     // on the command line: --planner NAME
  std::string summary;  // one line for --help and docs
  Capabilities can;
  // True: searches the task the reasoning simplified, each step checked by kappa's validity rules. False:
  // the formula as written, contacts with fixed bodies its only rule (the paper's simple planner).
  bool uses_knowledge = true;
  std::vector<PlannerParameter> parameters;
  // Rules of its own that refuse a step (heuristic cuts, beside the semantic ones of refusal.h): their
  // names, Refusals::own()'s order.
  std::vector<std::string> own_refusals;
  // Keys its account may fill: in every report.json (and failed/report.json) of the program, null where
  // another planner ran, so that a report has the same keys whatever planner wrote it.
  std::vector<std::string> report_keys;
  std::vector<std::string> diagnosis_keys;

  // Run once per problem and kept (PlanningProblem::preparation): what the planner makes of the problem
  // before any search, as OMPL's setup(). Empty: nothing. Long loops check `options.deadline` (the first
  // run's) and throw DeadlineReached; nothing is kept then.
  std::function<std::shared_ptr<const PlannerData>(const Problem&, const PreparationOptions& options)> prepare;
  // The search; `prepared` is what prepare made (null without it).
  std::function<PlanResult(const Problem&, const PlannerData* prepared, const PlannerOptions&)> plan;
  // Its own data, from prepare or from PlanResult::own, in the program's forms. Empty: it shows none.
  std::function<PlannerAccount(const PlannerData&, const scenario::World&)> account;
};

// Why `planner` cannot take `task` (and `needs`), in a sentence; nothing when it can.
std::optional<std::string> cannot_take(const PlannerEntry& planner, const TaskAutomaton& task, Needs needs = {});

}  // namespace physltl::planning
