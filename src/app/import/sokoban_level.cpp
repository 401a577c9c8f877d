#include "sokoban_level.h"

#include "common/bad_input.h"

#include <algorithm>
#include <fstream>

namespace physltl::app::import {
namespace {

constexpr const char* kLevelCharacters = "#@+$*. -_";

bool is_level_row(const std::string& line) {
  const auto first = line.find_first_not_of(' ');
  return first != std::string::npos && line[first] == '#';
}

[[noreturn]] void refuse(const std::filesystem::path& file, int line, const std::string& message) {
  throw BadInput(file.string() + ":" + std::to_string(line) + ": " + message);
}

// The player must be walled in: a flood over the floor from the player never leaves the rows.
bool walled_in(const SokobanLevel& level) {
  std::vector<std::string> seen = level.rows;
  std::vector<Cell> todo{level.player};
  while (!todo.empty()) {
    const Cell c = todo.back();
    todo.pop_back();
    if (c.row < 0 || c.row >= static_cast<int>(seen.size()) || c.column < 0 ||
        c.column >= static_cast<int>(seen[static_cast<size_t>(c.row)].size())) {
      return false;
    }
    char& here = seen[static_cast<size_t>(c.row)][static_cast<size_t>(c.column)];
    if (here == '#' || here == 'v') continue;
    here = 'v';
    for (const Cell next : {Cell{c.row - 1, c.column}, Cell{c.row + 1, c.column}, Cell{c.row, c.column - 1},
                            Cell{c.row, c.column + 1}}) {
      todo.push_back(next);
    }
  }
  return true;
}

SokobanLevel finish_level(const std::filesystem::path& file, SokobanLevel level) {
  int players = 0;
  for (int r = 0; r < static_cast<int>(level.rows.size()); ++r) {
    const std::string& row = level.rows[static_cast<size_t>(r)];
    for (int c = 0; c < static_cast<int>(row.size()); ++c) {
      const char ch = row[static_cast<size_t>(c)];
      if (ch == '@' || ch == '+') {
        level.player = {r, c};
        ++players;
      }
      if (ch == '$' || ch == '*') level.boxes.push_back({r, c});
      if (ch == '.' || ch == '*' || ch == '+') level.goals.push_back({r, c});
    }
  }
  const std::string which = "level " + std::to_string(level.number) + ": ";
  if (players != 1) refuse(file, level.line, which + "needs exactly one player (@ or +), has " + std::to_string(players));
  if (level.boxes.empty()) refuse(file, level.line, which + "has no box ($ or *)");
  if (level.boxes.size() != level.goals.size()) {
    refuse(file, level.line, which + std::to_string(level.boxes.size()) + " boxes but " +
                                 std::to_string(level.goals.size()) + " goals");
  }
  if (!walled_in(level)) refuse(file, level.line, which + "the player is not walled in (#)");
  return level;
}

}  // namespace

int SokobanLevel::width() const {
  std::size_t w = 0;
  for (const auto& row : rows) w = std::max(w, row.size());
  return static_cast<int>(w);
}

std::vector<SokobanLevel> read_sokoban_levels(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw BadInput("cannot read " + file.string());
  std::vector<SokobanLevel> levels;
  SokobanLevel current;
  std::string line;
  int number = 0;
  const auto close = [&] {
    if (!current.rows.empty()) levels.push_back(finish_level(file, std::move(current)));
    current = SokobanLevel{};
  };
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (!is_level_row(line)) {
      close();
      continue;
    }
    const auto bad = line.find_first_not_of(kLevelCharacters);
    if (bad != std::string::npos) {
      refuse(file, number, std::string("'") + line[bad] + "' at column " + std::to_string(bad + 1) +
                               " is no Sokoban cell (# @ + $ * . space - _)");
    }
    if (current.rows.empty()) {
      current.number = static_cast<int>(levels.size()) + 1;
      current.line = number;
    }
    std::replace(line.begin(), line.end(), '-', ' ');
    std::replace(line.begin(), line.end(), '_', ' ');
    current.rows.push_back(line);
  }
  close();
  if (levels.empty()) throw BadInput(file.string() + ": no Sokoban level in it (rows start with #)");
  return levels;
}

}  // namespace physltl::app::import
