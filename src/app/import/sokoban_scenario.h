#pragma once
// A Sokoban level as a Lua scenario (docs/scenarios.md#importing-sokoban-levels): walls merged into
// rectangles, boxes as movable bodies M1.. in the group `boxes`, goals as regions goal1.. in the group
// `goals`, the player as the robot, and the task F G(boxes@goals): any box on any goal, for any number.

#include "sokoban_level.h"
#include "sokoban_solution.h"

#include <optional>
#include <string>

namespace physltl::app::import {

struct GridSizes {
  double cell = 0.6;          // m
  double box = 0.5;           // m, a box's side
  double robot_radius = 0.25; // m
};

// `reference`, when given, is the level's solution as replayed on its grid (sokoban_solution.h), named by
// its file: the scenario's comment gives its moves and pushes, what a plan's pushes compare with.
struct ReferenceSolution {
  std::string file;
  SolutionReplay replay;
};
std::string sokoban_scenario(const SokobanLevel& level, const std::string& source, const GridSizes& sizes,
                             const std::optional<ReferenceSolution>& reference = std::nullopt);

// Why `check` would refuse the scenario of `level`, with the limit it shares with the scenario reader and
// the planner: more wall rectangles or boxes than a scenario may hold (scenario::kMaxFixedBodies, kMaxMovableBodies); nothing
// when it would not.
std::optional<std::string> beyond_limits(const SokobanLevel& level);

}  // namespace physltl::app::import
