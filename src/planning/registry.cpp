#include "physltl/planning/registry.h"

#include <stdexcept>

namespace physltl::planning {

PlannerRegistry& PlannerRegistry::instance() {
  static PlannerRegistry registry = [] {
    PlannerRegistry built_in;
    add_builtin_planners(built_in);
    return built_in;
  }();
  return registry;
}

const PlannerEntry& PlannerRegistry::add(PlannerEntry entry) {
  if (find(entry.name) != nullptr) throw std::invalid_argument("a planner named '" + entry.name + "' is registered already");
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

const PlannerEntry& PlannerRegistry::default_planner() const { return *find("knowledge"); }
const PlannerEntry& PlannerRegistry::reference_planner() const { return *find("baseline"); }

std::optional<std::string> PlannerRegistry::refusal(const PlannerEntry& planner, const TaskAutomaton& task,
                                                    Needs needs) const {
  const auto refuse = [&](const std::string& what, Capability Capabilities::*capability) {
    std::vector<std::string> able;
    for (const PlannerEntry& entry : entries_) {
      if ((entry.can.*capability).can) able.push_back(entry.name);
    }
    std::string message = planner.name + " cannot take " + what + ": " + (planner.can.*capability).because;
    for (size_t i = 0; i < able.size(); ++i) {
      message += (i == 0 ? ": use " : i + 1 == able.size() ? " or " : ", ") + able[i];
    }
    return message;
  };
  if (task.names_bodies() && !planner.can.object_tasks.can) {
    return refuse("tasks about where bodies are (BODY@REGION)", &Capabilities::object_tasks);
  }
  if (task.ends_at_rest() && !planner.can.tasks_ending_at_rest.can) {
    return refuse("a task that only a plan ending at rest satisfies", &Capabilities::tasks_ending_at_rest);
  }
  if (needs.propagation_budget && !planner.can.propagation_budget.can) {
    return refuse("a budget of propagations", &Capabilities::propagation_budget);
  }
  return std::nullopt;
}

}  // namespace physltl::planning
