#include "sokoban_level.h"

#include "physltl/common/bad_input.h"
#include "physltl/common/files.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <sstream>

namespace physltl::app::import {
namespace {

constexpr const char* kLevelCharacters = "#@+$*. -_";

bool is_level_row(const std::string& line) {
  const auto first = line.find_first_not_of(' ');
  return first != std::string::npos && line[first] == '#';
}

// A row written run-length encoded ("5#", "#3 #"): digits among the cells, a wall in it.
bool is_run_length_row(const std::string& line) {
  const auto first = line.find_first_not_of(' ');
  return first != std::string::npos && std::isdigit(static_cast<unsigned char>(line[first])) != 0 &&
         line.find('#') != std::string::npos && line.find_first_not_of("0123456789#@+$*. -_|") == std::string::npos;
}

// The largest collections in use are a few megabytes; a file beyond this is not a collection of levels.
constexpr std::size_t kMaxFileBytes = std::size_t{16} << 20;
// Rows and columns of a level: beyond any published one, and far beyond what a scenario can hold.
constexpr std::size_t kMaxLevelSide = 500;

// A character as a message shows it: printable as itself, anything else by its code.
std::string shown(char c) {
  const auto byte = static_cast<unsigned char>(c);
  if (byte >= 0x20 && byte < 0x7f) return std::string("'") + c + "'";
  return fmt::format("the byte 0x{:02x}", byte);
}

[[noreturn]] void refuse(const std::filesystem::path& file, int line, const std::string& message) {
  throw common::BadInput(file.string() + ":" + std::to_string(line) + ": " + message);
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
  std::string text = common::read_input_file(file, kMaxFileBytes);
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);  // a UTF-8 byte-order mark
  std::istringstream in(text);
  std::vector<SokobanLevel> levels;
  SokobanLevel current;
  std::string line;
  int number = 0;
  const auto close = [&] {
    if (!current.rows.empty()) levels.push_back(finish_level(file, std::move(current)));
    current = SokobanLevel{};
  };
  bool in_comment_block = false;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    // "Comment:" alone on its line opens a block of free text up to "Comment-End:" (the format of
    // collections such as cavepacker's): a line of it that starts with '#' is no row.
    if (in_comment_block || line == "Comment:") {
      in_comment_block = line != "Comment-End:";
      close();
      continue;
    }
    // A comment inside a level (some collections put one between its rows) does not end it.
    if (!current.rows.empty() && line.rfind(";", 0) == 0) continue;
    if (is_run_length_row(line)) refuse(file, number, "a run-length encoded row (digits before the cells): write the level out cell by cell");
    if (!is_level_row(line)) {
      close();
      continue;
    }
    const auto bad = line.find_first_not_of(kLevelCharacters);
    if (bad != std::string::npos) {
      const bool run_length = std::isdigit(static_cast<unsigned char>(line[bad])) != 0;
      refuse(file, number, run_length ? "a run-length encoded row (digits before the cells): write the level out cell by cell"
                                      : shown(line[bad]) + " at column " + std::to_string(bad + 1) +
                                            " is no Sokoban cell (# @ + $ * . space - _)");
    }
    if (line.size() > kMaxLevelSide || current.rows.size() >= kMaxLevelSide) {
      refuse(file, number, "a level wider or taller than " + std::to_string(kMaxLevelSide) + " cells");
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
  if (levels.empty()) throw common::BadInput(file.string() + ": no Sokoban level in it (rows start with #)");
  return levels;
}

}  // namespace physltl::app::import
