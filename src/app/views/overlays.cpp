#include "overlays.h"

#include "physltl/ltl/formula.h"

#include <algorithm>

namespace physltl::app {

std::vector<render::MRegionOverlay> mregion_overlays(const knowledge::AbstractKnowledge& knowledge,
                                                     const knowledge::Kappa& kappa,
                                                     const scenario::EnvironmentState& state) {
  std::vector<render::MRegionOverlay> overlays;
  for (std::size_t i = 0; i < knowledge.movable_bodies.size(); ++i) {
    const geometry::Pose2& pose = state.movable_poses.at(i);
    for (const knowledge::MRegionTemplate& m : knowledge.movable_bodies[i].mregions) {
      overlays.push_back({geometry::Polygon::from_box(knowledge::mregion_at(m, pose)),
                          kappa.bodies.at(i).active_faces.contains(m.face), static_cast<int>(i)});
    }
  }
  return overlays;
}

std::vector<render::ObjectGoalOverlay> object_goal_overlays(const scenario::World& world, const knowledge::Reasoning& reasoning,
                                                            const scenario::EnvironmentState& state) {
  std::vector<render::ObjectGoalOverlay> goals;
  for (const knowledge::ObjectVerdict& object : reasoning.feasibility.objects) {
    if (object.bodies.size() != 1 || object.regions.size() != 1) continue;  // a group's: object_group_lines
    const int body = object.bodies.front(), region = object.regions.front();
    const bool holds = world.regions[static_cast<size_t>(region)].polygon.contains(state.movable_poses[static_cast<size_t>(body)].position);
    goals.push_back({body, region, holds});
  }
  return goals;
}

std::string object_goal_line(const scenario::World& world, const render::ObjectGoalOverlay& goal) {
  return world.movable_bodies[static_cast<size_t>(goal.body)].name + " -> " +
         world.regions[static_cast<size_t>(goal.region)].name + (goal.holds ? ": holds" : ": not yet");
}

std::vector<std::string> object_group_lines(const scenario::World& world, const knowledge::Reasoning& reasoning,
                                            const scenario::EnvironmentState& state, bool all_in) {
  std::vector<std::string> lines;
  for (const knowledge::ObjectVerdict& object : reasoning.feasibility.objects) {
    if (object.bodies.size() == 1 && object.regions.size() == 1) continue;  // object_goal_overlays
    const auto inside = [&](int body) {
      return std::any_of(object.regions.begin(), object.regions.end(), [&](int r) {
        return world.regions[static_cast<size_t>(r)].polygon.contains(state.movable_poses[static_cast<size_t>(body)].position);
      });
    };
    const auto count = all_in ? object.bodies.size() : static_cast<std::size_t>(std::count_if(object.bodies.begin(), object.bodies.end(), inside));
    lines.push_back(object.body + " -> " + object.region + ": " + std::to_string(count) + " of " +
                    std::to_string(object.bodies.size()) + " in");
  }
  return lines;
}

render::Overlay preview_overlay(const scenario::World& world, const knowledge::Reasoning& r) {
  render::Overlay overlay;
  overlay.mregions = mregion_overlays(r.knowledge, r.initial_kappa, r.initial_state);
  overlay.avoided_regions = ltl::avoided_propositions(r.task.normal_form);
  overlay.object_goals = object_goal_overlays(world, r, r.initial_state);
  overlay.legend.push_back("task: " + ltl::to_string(r.task.input));
  for (const knowledge::InvalidProposition& p : r.feasibility.invalid) overlay.legend.push_back("unreachable " + p.reason);
  const std::optional<ltl::Formula> simplified = r.simplified_formula();
  overlay.legend.push_back(simplified ? "planned: " + ltl::to_string(*simplified) : "infeasible");
  if (!overlay.mregions.empty()) overlay.legend.push_back("mRegions: coloured = the robot may push from there, grey = blocked");
  if (!overlay.avoided_regions.empty()) overlay.legend.push_back("red: regions the task never enters");
  for (const render::ObjectGoalOverlay& goal : overlay.object_goals) overlay.legend.push_back(object_goal_line(world, goal));
  for (std::string& line : object_group_lines(world, r, r.initial_state)) overlay.legend.push_back(std::move(line));
  return overlay;
}

}  // namespace physltl::app
