#pragma once
// What a planner reports of its own (PlannerEntry::account) as the program's views show it: its keys in
// report.json and check --json, its refusal rules, its planned moves as arrows (docs/report.md).

#include "physltl/planning/planner_entry.h"
#include "physltl/planning/registry.h"
#include "physltl/render/scene.h"
#include "physltl/scenario/world.h"

#include <nlohmann/json.hpp>

#include <string>
#include <utility>
#include <vector>

namespace physltl::app {

// `planner`'s account of `data` (what it prepared, or PlanResult::own); empty without data or account.
planning::PlannerAccount account_of(const planning::PlannerEntry& planner, const planning::PlannerData* data,
                                    const scenario::World& world);

// Adds each of `keys` to `report` with its value in `values`, null where `values` has none: every report
// has the keys of every planner of the program, whatever planner wrote it.
void add_planner_keys(nlohmann::ordered_json& report, const std::vector<std::string>& keys, const nlohmann::ordered_json& values);

// {"fixed_contact": n, "task_letter": n, ...}
nlohmann::ordered_json refusals_json(const std::vector<std::pair<std::string, long long>>& counts);

// A planner's planned moves as arrows on the floor, from where each body's centre starts to where the move
// leaves it, the first lightest and the last darkest (tree.png and the frames), with the legend's line.
struct PlannedMoves {
  std::vector<render::SegmentOverlay> arrows;
  std::string legend;  // empty without arrows
};
PlannedMoves planned_moves(const planning::PlannerAccount& account);

}  // namespace physltl::app
