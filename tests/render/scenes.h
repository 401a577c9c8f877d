#pragma once
// The fixed inputs of the golden images: the paper's two worlds and synthetic overlays standing in for what
// the knowledge layer and the planner will provide.

#include "physltl/render/scene.h"
#include "physltl/scenario/load.h"
#include "physltl/scenario/world.h"

#include <string>

namespace physltl::render::test {

constexpr int kGoldenWidth = 320;
constexpr int kGoldenHeight = 240;

inline scenario::World paper_world(const std::string& name) {
  return scenario::load_scenario(std::string(PHYSLTL_SOURCE_DIR) + "/scenarios/" + name + ".lua");
}

// Four manipulation regions around each box of `world`, `depth` deep; the first `active` of them active.
Overlay mregions_around_boxes(const scenario::World& world, double depth, int active_per_box);

// A rapidly-exploring tree grown with a fixed pseudo-random sequence through the hall and room 2 of
// rooms.lua, coloured by the "automaton state" (hall or room), a path to p2 and a coarse triangulation.
Overlay synthetic_tree_of_rooms();

}  // namespace physltl::render::test
