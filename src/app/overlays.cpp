#include "overlays.h"

#include "physltl/ltl/formula.h"

namespace physltl::app {

std::vector<render::MRegionOverlay> mregion_overlays(const knowledge::AbstractKnowledge& knowledge,
                                                     const knowledge::Kappa& kappa,
                                                     const scenario::EnvironmentState& state) {
  std::vector<render::MRegionOverlay> overlays;
  for (std::size_t i = 0; i < knowledge.movable_bodies.size(); ++i) {
    const geometry::Pose2& pose = state.movable_poses.at(i);
    for (const knowledge::MRegionTemplate& m : knowledge.movable_bodies[i].mregions) {
      overlays.push_back({geometry::Polygon::from_box(knowledge::mregion_at(m, pose)),
                          kappa.bodies.at(i).active_sides.contains(m.side)});
    }
  }
  return overlays;
}

render::Overlay preview_overlay(const Reasoning& r) {
  render::Overlay overlay;
  overlay.mregions = mregion_overlays(r.knowledge, r.initial_kappa, r.initial_state);
  overlay.avoided_regions = ltl::avoided_propositions(r.task.normal_form);
  overlay.legend.push_back("task: " + ltl::to_string(r.task.input));
  for (const knowledge::InvalidProposition& p : r.feasibility.invalid) overlay.legend.push_back("unreachable " + p.reason);
  const std::optional<ltl::Formula> simplified = r.simplified_formula();
  overlay.legend.push_back(simplified ? "planned: " + ltl::to_string(*simplified) : "infeasible");
  if (!overlay.mregions.empty()) overlay.legend.push_back("mRegions: coloured = the robot may push from there, grey = blocked");
  if (!overlay.avoided_regions.empty()) overlay.legend.push_back("red: regions the task never enters");
  return overlay;
}

}  // namespace physltl::app
