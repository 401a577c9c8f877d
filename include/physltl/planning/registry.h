#pragma once
// The planners by name: what each can take and how to run it. run, bench, execute, --help and every
// refusal ask this registry, so a new planner is one folder of src/planning and one entry
// (docs/planner.md, "Adding a planner").

#include "physltl/planning/planner_options.h"
#include "physltl/planning/problem.h"

#include <deque>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
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

struct PlannerEntry {
  std::string name;     // on the command line: --planner NAME
  std::string summary;  // one line for --help and docs
  Capabilities can;
  // True: searches the task the reasoning simplified, each step checked by kappa's validity rules. False:
  // the formula as written, contacts with fixed bodies its only rule (the paper's simple planner).
  bool uses_knowledge = true;
  std::function<PlanResult(const Problem&, const PlannerOptions&)> plan;
};

// What a caller asks of a planner beyond the task.
struct Needs {
  bool propagation_budget = false;
};

class PlannerRegistry {
 public:
  // The process's registry, holding the built-in planners (planners.cpp) and whatever was added since.
  static PlannerRegistry& instance();

  // std::invalid_argument for a name already taken. Entries stay where they are: pointers to them last.
  const PlannerEntry& add(PlannerEntry entry);
  const PlannerEntry* find(std::string_view name) const;
  const std::deque<PlannerEntry>& entries() const { return entries_; }
  // "knowledge, baseline, ompl-ltl, ...": all of them, or those that have `capability`.
  std::string names(Capability Capabilities::*capability = nullptr) const;
  // The planner a run uses when none is named (the paper's, with knowledge), and the knowledge-free
  // reference it is measured against (--compare, --baseline, bench's speed-up column).
  const PlannerEntry& default_planner() const;
  const PlannerEntry& reference_planner() const;

  // Why `planner` cannot take `task` (and `needs`), in a sentence naming the planners that can; nothing
  // when it can.
  std::optional<std::string> refusal(const PlannerEntry& planner, const TaskAutomaton& task, Needs needs = {}) const;

 private:
  std::deque<PlannerEntry> entries_;
};

// Adds the planners this build has: ours (knowledge, baseline) and OMPL's.
void add_builtin_planners(PlannerRegistry& registry);

}  // namespace physltl::planning
