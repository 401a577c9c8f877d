#pragma once
// What the app's pictures show beyond the World: mRegions from the knowledge layer and a legend.

#include "physltl/knowledge/abstract_knowledge.h"
#include "physltl/knowledge/kappa.h"
#include "physltl/render/scene.h"
#include "physltl/scenario/state.h"
#include "reasoning.h"

#include <vector>

namespace physltl::app {

// Every movable body's mRegions at its pose in `state`, active as `kappa` says: where the robot may push
// from now. Frames of a plan call it with each step's state and kappa.
std::vector<render::MRegionOverlay> mregion_overlays(const knowledge::AbstractKnowledge& knowledge,
                                                     const knowledge::Kappa& kappa,
                                                     const scenario::EnvironmentState& state);

// preview.png's overlay: kappa_0's mRegions and a legend with the task, its simplification (or why it is
// infeasible) and the invalid propositions.
render::Overlay preview_overlay(const Reasoning& reasoning);

}  // namespace physltl::app
