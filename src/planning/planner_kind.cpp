#include "physltl/planning/planner_kind.h"

#include <array>
#include <utility>

namespace physltl::planning {
namespace {

constexpr std::array<std::pair<PlannerKind, const char*>, 7> kPlannerNames = {{
    {PlannerKind::kKnowledge, "knowledge"},
    {PlannerKind::kBaseline, "baseline"},
    {PlannerKind::kOmplLtl, "ompl-ltl"},
    {PlannerKind::kOmplRrt, "ompl-rrt"},
    {PlannerKind::kOmplKpiece, "ompl-kpiece"},
    {PlannerKind::kOmplSst, "ompl-sst"},
    {PlannerKind::kOmplPdst, "ompl-pdst"},
}};

}  // namespace

const char* planner_name(PlannerKind planner) {
  for (const auto& [kind, name] : kPlannerNames) {
    if (kind == planner) return name;
  }
  return "?";
}

std::optional<PlannerKind> planner_from_name(std::string_view name) {
  for (const auto& [kind, known] : kPlannerNames) {
    if (name == known) return kind;
  }
  return std::nullopt;
}

const std::vector<PlannerKind>& all_planners() {
  static const std::vector<PlannerKind> planners = [] {
    std::vector<PlannerKind> all;
    for (const auto& entry : kPlannerNames) all.push_back(entry.first);
    return all;
  }();
  return planners;
}

bool is_ompl(PlannerKind planner) { return planner != PlannerKind::kKnowledge && planner != PlannerKind::kBaseline; }

std::optional<std::string> refusal(PlannerKind planner, const TaskAutomaton& task) {
  if (!is_ompl(planner)) return std::nullopt;
  if (task.names_bodies()) {
    return std::string(planner_name(planner)) + " cannot take tasks about where bodies are (BODY@REGION): OMPL's " +
           "product graph labels each triangle of the decomposition with one letter, the robot's region, so its " +
           "automaton never reads a body's place: plan it with knowledge or baseline";
  }
  if (!task.ends_at_rest()) return std::nullopt;
  return std::string(planner_name(planner)) + " plans co-safe tasks only (OMPL's product graph takes co-safe tasks, " +
         "and co-safe with safety, satisfied by a finite run), but this task is satisfied only by a plan that ends at " +
         "rest: plan it with knowledge or baseline";
}

knowledge::ValidityMode validity_mode(PlannerKind planner) {
  return planner == PlannerKind::kBaseline ? knowledge::ValidityMode::kBaseline : knowledge::ValidityMode::kKnowledge;
}

}  // namespace physltl::planning
