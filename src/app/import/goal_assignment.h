#pragma once
// From 6 boxes on, the importer gives each box one goal (docs/scenarios.md, "Importing Sokoban levels"):
// the assignment with the fewest pushes in all, each box pushed alone (the robot walking anywhere that is
// not a wall), so that no box is given a goal it can never be pushed to while another assignment has none.

#include "sokoban_level.h"

#include <vector>

namespace physltl::app::import {

// Per box (SokobanLevel::boxes order), the index of its goal.
std::vector<int> assign_goals(const SokobanLevel& level);

}  // namespace physltl::app::import
