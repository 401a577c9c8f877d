#pragma once
// What the app's pictures show beyond the World: mRegions from the knowledge layer and a legend.

#include "physltl/knowledge/abstract_knowledge.h"
#include "physltl/knowledge/kappa.h"
#include "physltl/render/scene.h"
#include "physltl/scenario/state.h"
#include "physltl/knowledge/reasoning.h"

#include <string>
#include <vector>

namespace physltl::app {

// Every movable body's mRegions at its pose in `state`, active as `kappa` says: where the robot may push
// from now. Frames of a plan call it with each step's state and kappa.
std::vector<render::MRegionOverlay> mregion_overlays(const knowledge::AbstractKnowledge& knowledge,
                                                     const knowledge::Kappa& kappa,
                                                     const scenario::EnvironmentState& state);

// The task's object propositions about one body and one region (BODY@REGION) as pictures show them, each
// holding or not in `state`.
std::vector<render::ObjectGoalOverlay> object_goal_overlays(const scenario::World& world, const knowledge::Reasoning& reasoning,
                                                            const scenario::EnvironmentState& state);
// The legend's line for one: "crate -> dock: holds" or "crate -> dock: not yet".
std::string object_goal_line(const scenario::World& world, const render::ObjectGoalOverlay& goal);
// The legend's line for each proposition about a group (scenarios.md#groups), how many of its bodies are
// in one of its regions in `state`: "boxes -> goals: 3 of 20 in"; with `all_in`, every one (the widest
// line a legend must leave room for).
std::vector<std::string> object_group_lines(const scenario::World& world, const knowledge::Reasoning& reasoning,
                                            const scenario::EnvironmentState& state, bool all_in = false);

// preview.png's overlay: kappa_0's mRegions, the object goals, and a legend with the task, its
// simplification (or why it is infeasible), the invalid propositions and the object goals.
render::Overlay preview_overlay(const scenario::World& world, const knowledge::Reasoning& reasoning);

}  // namespace physltl::app
