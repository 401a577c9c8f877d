#pragma once
// A Sokoban level as a Lua scenario (docs/scenarios.md#importing-sokoban-levels): walls merged into
// rectangles, boxes as movable bodies M1.., goals as regions goal1.., the player as the robot.

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

// Sokoban lets any box sit on any goal. Up to kMaxAnyBoxAnyGoal boxes the task says so,
// F G(&_j |_i Mi@goalj); the labelling tells (n + 1)^n fact sets apart, which exceeds its 2^16 from
// n = 6, so beyond that each box is given one goal (nearest pairs first, by grid distance) and the task is
// F G(M1@goalk & ...): a stronger task, which a level may need another assignment for.
inline constexpr int kMaxAnyBoxAnyGoal = 5;

// `reference`, when given, is the level's solution as replayed on its grid (sokoban_solution.h), named by
// its file: the scenario's comment gives its moves and pushes, what a plan's pushes compare with.
struct ReferenceSolution {
  std::string file;
  SolutionReplay replay;
};
std::string sokoban_scenario(const SokobanLevel& level, const std::string& source, const GridSizes& sizes,
                             const std::optional<ReferenceSolution>& reference = std::nullopt);

// Why `check` would refuse the scenario of `level`, with the limit it shares with the scenario reader and
// the planner: more wall rectangles or boxes than a scenario may hold (scenario::kMaxBodiesOfAKind), a task
// naming its boxes in more places together than the planner tells apart (knowledge::Labelling); nothing
// when it would not.
std::optional<std::string> beyond_limits(const SokobanLevel& level);

}  // namespace physltl::app::import
