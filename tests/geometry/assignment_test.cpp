// The cheapest assignment (geometry/assignment.h), the look-ahead's matching of boxes to goals.

#include "physltl/geometry/assignment.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

namespace physltl::geometry {
namespace {

constexpr int kNever = 1'000'000;

// Every way of giving the rows distinct columns, tried.
int cheapest_by_trying_all(const std::vector<int>& cost, int rows, int columns) {
  std::vector<int> columns_order(static_cast<std::size_t>(columns));
  std::iota(columns_order.begin(), columns_order.end(), 0);
  int best = kNever;
  do {
    int total = 0;
    for (int r = 0; r < rows && total < kNever; ++r) {
      const int c = cost[static_cast<std::size_t>(r * columns + columns_order[static_cast<std::size_t>(r)])];
      total = c >= kNever ? kNever : total + c;
    }
    best = std::min(best, total);
  } while (std::next_permutation(columns_order.begin(), columns_order.end()));
  return best;
}

TEST(Assignment, TwoRowsNearerTheSameColumnShareTheColumnsAtLeastCost) {
  Assignment assignment;
  // Both rows are nearest column 0 (cost 1 each); the cheapest gives it to the row for which column 1
  // costs more: row 0 on column 1 (2), row 1 on column 0 (1). Row 0 first on its nearest would cost 1 + 9.
  EXPECT_EQ(assignment.cheapest({1, 2, 1, 9}, 2, 2, kNever), 3);
  EXPECT_EQ(assignment.cheapest({1, 4, 2, 3}, 2, 2, kNever), 4);
}

TEST(Assignment, AvoidsForbiddenPairsAndSaysWhenNoAssignmentCan) {
  Assignment assignment;
  EXPECT_EQ(assignment.cheapest({kNever, 7, 1, 2}, 2, 2, kNever), 8);  // row 0 can only take column 1
  EXPECT_EQ(assignment.cheapest({kNever, 7, kNever, 2}, 2, 2, kNever), kNever);  // both need column 1
  EXPECT_EQ(assignment.cheapest({1, 2}, 2, 1, kNever), kNever);  // two rows, one column
  EXPECT_EQ(assignment.cheapest({}, 0, 3, kNever), 0);
}

TEST(Assignment, EqualsTryingEveryAssignmentOnRandomMatrices) {
  std::mt19937 random(7);
  Assignment assignment;
  for (int trial = 0; trial < 300; ++trial) {
    const int columns = 1 + trial % 6;
    const int rows = 1 + trial / 6 % columns;
    std::vector<int> cost(static_cast<std::size_t>(rows * columns));
    for (int& c : cost) c = random() % 10 == 0 ? kNever : static_cast<int>(random() % 20);
    EXPECT_EQ(assignment.cheapest(cost, rows, columns, kNever), cheapest_by_trying_all(cost, rows, columns)) << "trial " << trial;
  }
}

}  // namespace
}  // namespace physltl::geometry
