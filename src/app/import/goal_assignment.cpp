#include "goal_assignment.h"

#include <array>
#include <bit>
#include <cstddef>
#include <limits>
#include <stdexcept>

namespace physltl::app::import {
namespace {

// A goal a box can never be pushed to costs this many pushes: the assignment avoids it where it can.
constexpr int kUnreachable = 1'000'000;
// Over this many boxes the assignment's table (one entry per set of goals) would be too large; the
// scenario reader refuses such levels before (beyond_limits), so this is a guard, not a limit users meet.
constexpr int kMaxBoxes = 20;

constexpr std::array<int, 4> kRowStep = {-1, 1, 0, 0};
constexpr std::array<int, 4> kColumnStep = {0, 0, -1, 1};

bool floor_at(const SokobanLevel& level, int row, int column) {
  if (row < 0 || row >= static_cast<int>(level.rows.size()) || column < 0) return false;
  const std::string& line = level.rows[static_cast<std::size_t>(row)];
  return column < static_cast<int>(line.size()) && line[static_cast<std::size_t>(column)] != '#';
}

// Per cell (row * width + column), the fewest pushes of a box alone from `start` to it.
std::vector<int> pushes_from(const SokobanLevel& level, const Cell& start) {
  const int width = level.width();
  std::vector<int> pushes(level.rows.size() * static_cast<std::size_t>(width), kUnreachable);
  std::vector<Cell> queue{start};
  pushes[static_cast<std::size_t>(start.row * width + start.column)] = 0;
  for (std::size_t i = 0; i < queue.size(); ++i) {
    const Cell c = queue[i];
    const int here = pushes[static_cast<std::size_t>(c.row * width + c.column)];
    for (std::size_t d = 0; d < kRowStep.size(); ++d) {
      const Cell to{c.row + kRowStep[d], c.column + kColumnStep[d]};
      // The robot stands on the other side of the box from where it goes.
      if (!floor_at(level, to.row, to.column) || !floor_at(level, c.row - kRowStep[d], c.column - kColumnStep[d])) continue;
      int& there = pushes[static_cast<std::size_t>(to.row * width + to.column)];
      if (there != kUnreachable) continue;
      there = here + 1;
      queue.push_back(to);
    }
  }
  return pushes;
}

}  // namespace

std::vector<int> assign_goals(const SokobanLevel& level) {
  const int n = static_cast<int>(level.boxes.size());
  if (n > kMaxBoxes || level.goals.size() != level.boxes.size()) throw std::invalid_argument("assign_goals: too many boxes or goals");
  const int width = level.width();
  std::vector<std::vector<int>> cost(static_cast<std::size_t>(n));
  for (int b = 0; b < n; ++b) {
    const std::vector<int> pushes = pushes_from(level, level.boxes[static_cast<std::size_t>(b)]);
    for (const Cell& g : level.goals) cost[static_cast<std::size_t>(b)].push_back(pushes[static_cast<std::size_t>(g.row * width + g.column)]);
  }
  // best[mask]: the fewest pushes giving the first popcount(mask) boxes the goals in mask; choice[mask]
  // the goal the last of those boxes takes. Ties go to the lower goal, so the result is the same on any
  // machine.
  const std::size_t sets = std::size_t{1} << n;
  std::vector<long long> best(sets, std::numeric_limits<long long>::max());
  std::vector<int> choice(sets, -1);
  best[0] = 0;
  for (std::size_t mask = 1; mask < sets; ++mask) {
    const int box = std::popcount(mask) - 1;
    for (int g = 0; g < n; ++g) {
      const std::size_t without = mask & ~(std::size_t{1} << g);
      if (without == mask || best[without] == std::numeric_limits<long long>::max()) continue;
      const long long total = best[without] + cost[static_cast<std::size_t>(box)][static_cast<std::size_t>(g)];
      if (total < best[mask]) best[mask] = total, choice[mask] = g;
    }
  }
  std::vector<int> goal_of(static_cast<std::size_t>(n));
  for (std::size_t mask = sets - 1; mask != 0; mask &= ~(std::size_t{1} << choice[mask])) {
    goal_of[static_cast<std::size_t>(std::popcount(mask) - 1)] = choice[mask];
  }
  return goal_of;
}

}  // namespace physltl::app::import
