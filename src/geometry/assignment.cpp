#include "physltl/geometry/assignment.h"

#include <limits>

namespace physltl::geometry {

int Assignment::cheapest(const std::vector<int>& cost, int rows, int columns, int never) {
  if (rows == 0) return 0;
  if (rows > columns) return never;
  // A forbidden pair costs more than any assignment without one, so the cheapest avoids it when it can.
  const long long forbidden = static_cast<long long>(never) * (rows + 1);
  const auto at = [&](int r, int c) -> long long {
    const int v = cost[static_cast<std::size_t>(r) * static_cast<std::size_t>(columns) + static_cast<std::size_t>(c)];
    return v >= never ? forbidden : v;
  };
  const long long infinity = std::numeric_limits<long long>::max() / 4;
  // Column 0 is a sentinel; rows and columns count from 1 below.
  row_potential_.assign(static_cast<std::size_t>(rows) + 1, 0);
  column_potential_.assign(static_cast<std::size_t>(columns) + 1, 0);
  row_of_column_.assign(static_cast<std::size_t>(columns) + 1, 0);
  way_.assign(static_cast<std::size_t>(columns) + 1, 0);
  for (int r = 1; r <= rows; ++r) {
    row_of_column_[0] = r;
    int column = 0;
    slack_.assign(static_cast<std::size_t>(columns) + 1, infinity);
    used_.assign(static_cast<std::size_t>(columns) + 1, false);
    do {
      used_[static_cast<std::size_t>(column)] = true;
      const int row = row_of_column_[static_cast<std::size_t>(column)];
      long long delta = infinity;
      int next = 0;
      for (int c = 1; c <= columns; ++c) {
        if (used_[static_cast<std::size_t>(c)]) continue;
        const long long reduced = at(row - 1, c - 1) - row_potential_[static_cast<std::size_t>(row)] - column_potential_[static_cast<std::size_t>(c)];
        if (reduced < slack_[static_cast<std::size_t>(c)]) slack_[static_cast<std::size_t>(c)] = reduced, way_[static_cast<std::size_t>(c)] = column;
        if (slack_[static_cast<std::size_t>(c)] < delta) delta = slack_[static_cast<std::size_t>(c)], next = c;
      }
      for (int c = 0; c <= columns; ++c) {
        if (used_[static_cast<std::size_t>(c)]) {
          row_potential_[static_cast<std::size_t>(row_of_column_[static_cast<std::size_t>(c)])] += delta;
          column_potential_[static_cast<std::size_t>(c)] -= delta;
        } else {
          slack_[static_cast<std::size_t>(c)] -= delta;
        }
      }
      column = next;
    } while (row_of_column_[static_cast<std::size_t>(column)] != 0);
    do {
      const int previous = way_[static_cast<std::size_t>(column)];
      row_of_column_[static_cast<std::size_t>(column)] = row_of_column_[static_cast<std::size_t>(previous)];
      column = previous;
    } while (column != 0);
  }
  long long total = 0;
  for (int c = 1; c <= columns; ++c) {
    if (row_of_column_[static_cast<std::size_t>(c)] != 0) total += at(row_of_column_[static_cast<std::size_t>(c)] - 1, c - 1);
  }
  return total >= forbidden ? never : static_cast<int>(total);
}

}  // namespace physltl::geometry
