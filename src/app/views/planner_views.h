#pragma once
// What a planner reports of its own (PlannerEntry::account) as the program's views show it: its keys in
// report.json and check --json, its refusal rules, its planned moves as arrows (docs/report.md).

#include "physltl/planning/planner_entry.h"
#include "physltl/planning/registry.h"
#include "physltl/render/scene.h"
#include "physltl/scenario/state_trace.h"
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
// leaves it, the first lightest and the last darkest (tree.png), with the legend's line; the frames of a
// plan draw them as they are carried out.
struct PlannedMoves {
  std::vector<planning::PlannerAccount::Move> moves;
  std::vector<render::SegmentOverlay> arrows;
  std::string legend;  // empty without arrows

  // With `done` moves carried out before state `step` of `trace`, how many are after it: move k is carried
  // out once move k - 1 is and its body's centre (any movable body's, where the move does not say) comes
  // near its end (within 45 % of its length, at most 30 cm: pushes leave a body where friction stops it,
  // not on the planned point).
  int carried_out(int done, const scenario::StateTrace& trace, std::size_t step) const;
  // The arrows as a frame shows them after `done` moves: those grey, the one under way red, the rest as
  // in `arrows`; and the legend's line, "look-ahead: push 3 of 6 under way". Where the plan has ended
  // with moves not carried out (an improved plan may reach the goal another way: other bodies, another
  // order), none is under way: "look-ahead: 5 of 6 pushes carried out as planned (grey)".
  std::vector<render::SegmentOverlay> arrows_after(int done, bool plan_ended = false) const;
  std::string legend_after(int done, bool plan_ended = false) const;
};
PlannedMoves planned_moves(const planning::PlannerAccount& account);

}  // namespace physltl::app
