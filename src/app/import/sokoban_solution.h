#pragma once
// A Sokoban solution (the LURD notation: u d l r for the player's moves, in capitals when the move pushes a
// box; run-length counts before a move or a parenthesised group, "3(ul)"; blanks and line breaks
// anywhere), replayed on the level's grid. A solution that replays proves the import read the level the
// way its author drew it, and gives the reference counts a planner's plan is measured against.

#include "sokoban_level.h"

#include <filesystem>
#include <string>

namespace physltl::app::import {

// More moves than any published solution (the longest run to tens of thousands): a count beyond this is
// a malformed or hostile file, refused before it is expanded.
inline constexpr long long kMaxSolutionMoves = 10'000'000;

struct SolutionReplay {
  long long moves = 0;
  long long pushes = 0;  // moves that pushed a box
};

// The moves of a solution file, expanded: "uuDL...". Throws BadInput naming FILE:LINE for a character
// that is no move, an unbalanced parenthesis, a count without a move or more than kMaxSolutionMoves.
std::string read_sokoban_solution(const std::filesystem::path& file);

// Plays `moves` on `level`. Throws BadInput, naming `source` and the move (by its number from 1), for a
// move into a wall, a push into a wall or another box, a capital that pushes nothing (the file and the
// level disagree), and for a solution that leaves a box off the goals. A small letter may push: many
// collections write every move small.
SolutionReplay replay_solution(const SokobanLevel& level, const std::string& moves, const std::string& source);

}  // namespace physltl::app::import
