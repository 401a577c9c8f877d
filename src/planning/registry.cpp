#include "physltl/planning/registry.h"

#include <algorithm>
#include <stdexcept>

namespace physltl::planning {
namespace {

void add_once(std::vector<std::string>& names, const std::vector<std::string>& more) {
  for (const std::string& name : more) {
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
}

// The capability `task` and `needs` ask of `planner` that it lacks, with what it is in words.
std::optional<std::pair<Capability Capabilities::*, const char*>> missing(const PlannerEntry& planner,
                                                                           const TaskAutomaton& task, Needs needs) {
  if (task.names_bodies() && !planner.can.object_tasks.can) {
    return std::pair{&Capabilities::object_tasks, "tasks about where bodies are (BODY@REGION)"};
  }
  if (task.ends_at_rest() && !planner.can.tasks_ending_at_rest.can) {
    return std::pair{&Capabilities::tasks_ending_at_rest, "a task that only a plan ending at rest satisfies"};
  }
  if (needs.propagation_budget && !planner.can.propagation_budget.can) {
    return std::pair{&Capabilities::propagation_budget, "a budget of propagations"};
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> cannot_take(const PlannerEntry& planner, const TaskAutomaton& task, Needs needs) {
  const auto lacking = missing(planner, task, needs);
  if (!lacking) return std::nullopt;
  return planner.name + " cannot take " + lacking->second + ": " + (planner.can.*lacking->first).because;
}

const PlannerEntry& PlannerRegistry::add(PlannerEntry entry) {
  if (find(entry.name) != nullptr) throw std::invalid_argument("a planner named '" + entry.name + "' is registered already");
  for (const PlannerParameter& parameter : entry.parameters) {
    for (const PlannerParameter* known : parameters()) {
      if (known->name == parameter.name && known->choices != parameter.choices) {
        throw std::invalid_argument("planner '" + entry.name + "' declares parameter '" + parameter.name +
                                    "' with other values than another planner's");
      }
    }
  }
  entries_.push_back(std::move(entry));
  return entries_.back();
}

const PlannerEntry* PlannerRegistry::find(std::string_view name) const {
  for (const PlannerEntry& entry : entries_) {
    if (entry.name == name) return &entry;
  }
  return nullptr;
}

std::string PlannerRegistry::names(Capability Capabilities::*capability) const {
  std::string names;
  for (const PlannerEntry& entry : entries_) {
    if (capability == nullptr || (entry.can.*capability).can) names += (names.empty() ? "" : ", ") + entry.name;
  }
  return names;
}

void PlannerRegistry::set_default_planners(const std::string& default_name, const std::string& reference_name) {
  default_ = find(default_name);
  reference_ = find(reference_name);
  if (default_ == nullptr || reference_ == nullptr) {
    throw std::invalid_argument("the default planners '" + default_name + "' and '" + reference_name + "' must be registered");
  }
}

const PlannerEntry& PlannerRegistry::default_planner() const {
  if (default_ == nullptr) throw std::logic_error("the registry has no default planner");
  return *default_;
}

const PlannerEntry& PlannerRegistry::reference_planner() const {
  if (reference_ == nullptr) throw std::logic_error("the registry has no reference planner");
  return *reference_;
}

std::optional<std::string> PlannerRegistry::refusal(const PlannerEntry& planner, const TaskAutomaton& task,
                                                    Needs needs) const {
  const auto lacking = missing(planner, task, needs);
  if (!lacking) return std::nullopt;
  std::string message = *cannot_take(planner, task, needs);
  std::vector<std::string> able;
  for (const PlannerEntry& entry : entries_) {
    if ((entry.can.*lacking->first).can) able.push_back(entry.name);
  }
  for (size_t i = 0; i < able.size(); ++i) {
    message += (i == 0 ? ": use " : i + 1 == able.size() ? " or " : ", ") + able[i];
  }
  return message;
}

std::vector<const PlannerParameter*> PlannerRegistry::parameters(Capability Capabilities::*capability) const {
  std::vector<const PlannerParameter*> all;
  for (const PlannerEntry& entry : entries_) {
    if (capability != nullptr && !(entry.can.*capability).can) continue;
    for (const PlannerParameter& parameter : entry.parameters) {
      const bool known = std::any_of(all.begin(), all.end(), [&](const PlannerParameter* p) { return p->name == parameter.name; });
      if (!known) all.push_back(&parameter);
    }
  }
  return all;
}

std::vector<std::string> PlannerRegistry::own_refusals() const {
  std::vector<std::string> names;
  for (const PlannerEntry& entry : entries_) add_once(names, entry.own_refusals);
  return names;
}

std::vector<std::string> PlannerRegistry::report_keys() const {
  std::vector<std::string> keys;
  for (const PlannerEntry& entry : entries_) add_once(keys, entry.report_keys);
  return keys;
}

std::vector<std::string> PlannerRegistry::diagnosis_keys() const {
  std::vector<std::string> keys;
  for (const PlannerEntry& entry : entries_) add_once(keys, entry.diagnosis_keys);
  return keys;
}

}  // namespace physltl::planning
