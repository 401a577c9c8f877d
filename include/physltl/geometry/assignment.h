#pragma once
// The cheapest assignment of rows to distinct columns (Kuhn and Munkres' Hungarian method with
// potentials, O(rows^2 * columns)): the look-ahead's lower bound when any box may take any goal, where it
// runs once per arrangement on a matrix of a few dozen entries. A graph library's general weighted
// matching would build a graph per call; this keeps one workspace between calls.

#include <vector>

namespace physltl::geometry {

class Assignment {
 public:
  // `cost[r * columns + c]`: what putting row r on column c costs, `never` where it cannot go. The least
  // total cost with every row on its own column, or `never` when no such assignment avoids `never`
  // (fewer columns than rows included).
  int cheapest(const std::vector<int>& cost, int rows, int columns, int never);

 private:
  std::vector<long long> row_potential_, column_potential_, slack_;
  std::vector<int> row_of_column_, way_;
  std::vector<bool> used_;
};

}  // namespace physltl::geometry
