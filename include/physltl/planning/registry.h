#pragma once
// The planners by name (planner_entry.h): run, bench, execute, --help and every refusal ask a registry,
// so a new planner is one folder of src/planners and one entry (docs/planner.md, "Adding a planner").
// The program's own registry, with the built-in planners, is planners::registry() (src/planners).

#include "physltl/planning/planner_entry.h"

#include <deque>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace physltl::planning {

class PlannerRegistry {
 public:
  // std::invalid_argument for a name already taken, or for a parameter of the same name as another
  // entry's but other choices. Entries stay where they are: pointers to them last.
  const PlannerEntry& add(PlannerEntry entry);
  const PlannerEntry* find(std::string_view name) const;
  const std::deque<PlannerEntry>& entries() const { return entries_; }
  // "knowledge, baseline, ompl-ltl, ...": all of them, or those that have `capability`.
  std::string names(Capability Capabilities::*capability = nullptr) const;
  // The planner a run uses when none is named, and the knowledge-free reference it is measured against
  // (--compare, --baseline, bench's speed-up column), both by name among the entries; std::invalid_argument
  // for a name not added.
  void set_default_planners(const std::string& default_name, const std::string& reference_name);
  const PlannerEntry& default_planner() const;
  const PlannerEntry& reference_planner() const;

  // Why `planner` cannot take `task` (and `needs`), in a sentence naming the planners that can; nothing
  // when it can.
  std::optional<std::string> refusal(const PlannerEntry& planner, const TaskAutomaton& task, Needs needs = {}) const;

  // Every planner's parameters, once each, in the order the entries declare them (a parameter several
  // planners take is one); with `capability`, those of the planners that have it.
  std::vector<const PlannerParameter*> parameters(Capability Capabilities::*capability = nullptr) const;
  // Every planner's own refusal rules, once each, in the order the entries name them.
  std::vector<std::string> own_refusals() const;
  // Every key any planner's account may write in report.json, and in failed/report.json besides.
  std::vector<std::string> report_keys() const;
  std::vector<std::string> diagnosis_keys() const;

 private:
  std::deque<PlannerEntry> entries_;
  const PlannerEntry* default_ = nullptr;
  const PlannerEntry* reference_ = nullptr;
};

}  // namespace physltl::planning
