// The look-ahead's store of arrangements (planners/knowledge/lookahead/arrangement_store.h): an
// arrangement met by two orders of pushes is one, the places of a settled one are rebuilt from its
// parent's and its push, and one met costs a few bytes however many bodies stand on the lattice.

#include "lookahead/arrangement_store.h"

#include <gtest/gtest.h>

#include <vector>

namespace physltl::planners::knowledge::lookahead {
namespace {

using Met = ArrangementStore::Met;

// Settles met arrangement m and returns its places.
std::vector<int> settle(ArrangementStore& store, int m, int cost, int* settled = nullptr) {
  std::vector<int> cells;
  const int s = store.settle(m, cost, cells);
  if (settled != nullptr) *settled = s;
  return cells;
}

TEST(ArrangementStore, AnArrangementReachedByTwoOrdersOfPushesIsMetOnce) {
  ArrangementStore store({0, 10});
  const int start = store.add({ArrangementStore::kStart, 5, 0, 0, 0, 0});
  ASSERT_EQ(start, 0);
  int s0 = -1;
  EXPECT_EQ(settle(store, start, 0, &s0), (std::vector<int>{0, 10}));

  // Body 0 first, then body 1; and body 1 first, then body 0: both end on {1, 11}.
  const int first = store.add({static_cast<std::uint32_t>(s0), 5, 0, 1, 0, 0});
  const int other = store.add({static_cast<std::uint32_t>(s0), 5, 0, 11, 1, 0});
  ASSERT_GE(first, 0);
  ASSERT_GE(other, 0);
  int s1 = -1, s2 = -1;
  EXPECT_EQ(settle(store, first, 1, &s1), (std::vector<int>{1, 10}));
  EXPECT_EQ(settle(store, other, 1, &s2), (std::vector<int>{0, 11}));
  const int both = store.add({static_cast<std::uint32_t>(s1), 5, 0, 11, 1, 0});
  ASSERT_GE(both, 0);
  EXPECT_EQ(store.add({static_cast<std::uint32_t>(s2), 5, 0, 1, 0, 0}), -1);
  // The same places with the robot in another component, or at another stage of the task, are new.
  EXPECT_GE(store.add({static_cast<std::uint32_t>(s2), 7, 0, 1, 0, 0}), 0);
  EXPECT_GE(store.add({static_cast<std::uint32_t>(s2), 5, 3, 1, 0, 0}), 0);
  // And pushed back to where it started, a body makes the start again.
  EXPECT_EQ(store.add({static_cast<std::uint32_t>(s1), 5, 0, 0, 0, 1}), -1);

  int s3 = -1;
  EXPECT_EQ(settle(store, both, 2, &s3), (std::vector<int>{1, 11}));
  EXPECT_EQ(store.settled_cost(s3), 2);
  EXPECT_EQ(store.settled_met(s3), both);
  EXPECT_EQ(store.met(both).parent, static_cast<std::uint32_t>(s1));
}

// What lets a search meet millions: an arrangement met and not settled keeps no places, so 30 bodies
// cost it no more than one (the store this replaced kept about 220 bytes for 27 bodies).
TEST(ArrangementStore, AnArrangementMetCostsTheSameFewBytesWhateverTheBodies) {
  for (int bodies : {1, 30}) {
    SCOPED_TRACE(bodies);
    std::vector<int> start(static_cast<std::size_t>(bodies));
    for (int k = 0; k < bodies; ++k) start[static_cast<std::size_t>(k)] = 2 * k;
    ArrangementStore store(start);
    std::vector<int> cells;
    const int s = store.settle(store.add({ArrangementStore::kStart, 0, 0, 0, 0, 0}), 0, cells);
    const int met = 200'000;
    for (int i = 1; i <= met; ++i) {
      ASSERT_GE(store.add({static_cast<std::uint32_t>(s), i, 0, 1, 0, 0}), 0);
    }
    EXPECT_EQ(store.met_count(), static_cast<std::size_t>(met) + 1);
    EXPECT_LT(store.bytes() / static_cast<std::size_t>(met), 40U) << store.bytes();
  }
}

}  // namespace
}  // namespace physltl::planners::knowledge::lookahead
