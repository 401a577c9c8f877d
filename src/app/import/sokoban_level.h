#pragma once
// Levels of the standard Sokoban text format (# wall, @ player, + player on goal, $ box, * box on goal,
// . goal, space, - or _ floor); lines of other text (titles, ';' comments, blank lines, a block from a
// line "Comment:" to a line "Comment-End:") separate levels.

#include <filesystem>
#include <string>
#include <vector>

namespace physltl::app::import {

struct Cell {
  int row = 0, column = 0;  // row 0 at the top, as the file draws it
};

struct SokobanLevel {
  int number = 0;  // from 1, in file order
  int line = 0;    // of its first row in the file
  std::vector<std::string> rows;
  Cell player;
  std::vector<Cell> boxes, goals;  // in reading order
  int width() const;
};

// Throws BadInput naming FILE:LINE for a level row with a character the format does not have, a level
// without exactly one player, with boxes and goals of different counts or none, or whose player is not
// walled in.
std::vector<SokobanLevel> read_sokoban_levels(const std::filesystem::path& file);

}  // namespace physltl::app::import
