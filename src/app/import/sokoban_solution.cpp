#include "sokoban_solution.h"

#include "physltl/common/bad_input.h"
#include "physltl/common/files.h"
#include "physltl/common/printable.h"

#include <fmt/format.h>

#include <cctype>
#include <optional>
#include <string_view>
#include <vector>

namespace physltl::app::import {
namespace {

constexpr std::size_t kMaxSolutionFileBytes = std::size_t{16} << 20;
// Groups inside groups: solutions as collections ship them nest two or three deep.
constexpr std::size_t kMaxSolutionNesting = 64;
constexpr std::string_view kMoves = "udlrUDLR";

// The moves of one parenthesised group (the whole solution at the bottom of the stack) and the count
// written before its '('.
struct Group {
  std::string moves;
  long long count = 1;
  int line = 0;
};

class SolutionReader {
 public:
  explicit SolutionReader(const std::filesystem::path& file) : file_(file) {}

  std::string read(const std::string& text) {
    stack_.push_back({});
    for (const char c : text) {
      if (c == '\n') ++line_;
      if (std::isspace(static_cast<unsigned char>(c)) != 0) continue;
      if (std::isdigit(static_cast<unsigned char>(c)) != 0) {
        count_ = count_.value_or(0) * 10 + (c - '0');
        if (*count_ > kMaxSolutionMoves) refuse(fmt::format("a count over {} moves", kMaxSolutionMoves));
      } else if (c == '(') {
        if (stack_.size() > kMaxSolutionNesting) refuse(fmt::format("groups nested deeper than {}", kMaxSolutionNesting));
        stack_.push_back({"", take_count(), line_});
      } else if (c == ')') {
        close_group();
      } else if (kMoves.find(c) != std::string_view::npos) {
        append(std::string(1, c), take_count());
      } else {
        refuse(fmt::format("'{}' is no move (u d l r, capitals for pushes, counts and parentheses)", common::printable(std::string(1, c))));
      }
    }
    if (count_) refuse("a count with no move after it");
    if (stack_.size() > 1) refuse(fmt::format("the '(' of line {} is never closed", stack_.back().line));
    if (stack_.back().moves.empty()) throw common::BadInput(file_.string() + ": no moves in it");
    return std::move(stack_.back().moves);
  }

 private:
  long long take_count() {
    const long long n = count_.value_or(1);
    if (n == 0) refuse("a count of 0");
    count_.reset();
    return n;
  }

  void close_group() {
    if (stack_.size() == 1) refuse("a ')' with no '(' before it");
    if (count_) refuse("a count with no move after it");
    Group group = std::move(stack_.back());
    // Repeating nothing costs its count in time and means nothing: "9999999()" nested was minutes of it.
    if (group.moves.empty()) refuse("a group with no moves in it");
    stack_.pop_back();
    held_ -= static_cast<long long>(group.moves.size());
    append(group.moves, group.count);
  }

  // Every group's moves held at once stay within kMaxSolutionMoves, so nested counts cannot blow up.
  void append(const std::string& moves, long long count) {
    const auto size = static_cast<long long>(moves.size());
    if (size > 0 && count > (kMaxSolutionMoves - held_) / size) refuse(fmt::format("more than {} moves", kMaxSolutionMoves));
    for (long long i = 0; i < count; ++i) stack_.back().moves += moves;
    held_ += size * count;
  }

  [[noreturn]] void refuse(const std::string& message) const {
    throw common::BadInput(file_.string() + ":" + std::to_string(line_) + ": " + message);
  }

  std::filesystem::path file_;
  std::vector<Group> stack_;
  std::optional<long long> count_;
  long long held_ = 0;
  int line_ = 1;
};

struct Step {
  int drow, dcolumn;
};

Step step_of(char move) {
  switch (std::tolower(static_cast<unsigned char>(move))) {
    case 'u': return {-1, 0};
    case 'd': return {1, 0};
    case 'l': return {0, -1};
    default: return {0, 1};
  }
}

// The level's cells as the replay sees them: '#' a wall (and everything outside the rows), 'B' a box,
// ' ' free.
class BoxGrid {
 public:
  explicit BoxGrid(const SokobanLevel& level) : cells_(level.rows) {
    for (std::string& row : cells_) {
      for (char& c : row) c = c == '#' ? '#' : ' ';
    }
    for (const Cell& box : level.boxes) cell(box) = 'B';
  }
  char at(const Cell& c) const { return inside(c) ? cells_[static_cast<std::size_t>(c.row)][static_cast<std::size_t>(c.column)] : '#'; }
  void move_box(const Cell& from, const Cell& to) {
    cell(from) = ' ';
    cell(to) = 'B';
  }

 private:
  bool inside(const Cell& c) const {
    return c.row >= 0 && c.row < static_cast<int>(cells_.size()) && c.column >= 0 &&
           c.column < static_cast<int>(cells_[static_cast<std::size_t>(c.row)].size());
  }
  char& cell(const Cell& c) { return cells_[static_cast<std::size_t>(c.row)][static_cast<std::size_t>(c.column)]; }
  std::vector<std::string> cells_;
};

}  // namespace

std::string read_sokoban_solution(const std::filesystem::path& file) {
  return SolutionReader(file).read(common::read_input_file(file, kMaxSolutionFileBytes));
}

SolutionReplay replay_solution(const SokobanLevel& level, const std::string& moves, const std::string& source) {
  BoxGrid grid(level);
  Cell player = level.player;
  SolutionReplay replay;
  for (const char move : moves) {
    ++replay.moves;
    const auto refuse = [&](const std::string& what) {
      throw common::BadInput(fmt::format("{}: move {} ('{}') of level {} {}", source, replay.moves, move, level.number, what));
    };
    const Step s = step_of(move);
    const Cell next{player.row + s.drow, player.column + s.dcolumn};
    const Cell beyond{next.row + s.drow, next.column + s.dcolumn};
    if (grid.at(next) == '#') refuse("walks into a wall");
    if (grid.at(next) == 'B') {
      if (grid.at(beyond) != ' ') refuse(grid.at(beyond) == 'B' ? "pushes a box into another box" : "pushes a box into a wall");
      grid.move_box(next, beyond);
      ++replay.pushes;
    } else if (std::isupper(static_cast<unsigned char>(move)) != 0) {
      refuse("is a push (a capital) but there is no box to push");
    }
    player = next;
  }
  int off_goal = 0;
  for (const Cell& goal : level.goals) off_goal += grid.at(goal) == 'B' ? 0 : 1;
  if (off_goal > 0) {
    throw common::BadInput(fmt::format("{}: the solution of level {} ends with {} of its {} goals without a box", source,
                               level.number, off_goal, level.goals.size()));
  }
  return replay;
}

}  // namespace physltl::app::import
