#include "lead_search.h"

#include "product_path.h"
#include "test_problem.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace physltl::planning {
namespace {

using namespace physltl::planners::knowledge;

TEST(LeadSearch, KeepsThePartBeforeTheFrontierAndSearchesTheRestAgain) {
  const TestProblem p("ordered.lua");
  const StageGraph stages(p.task);
  ProductGraph graph(p.decomposition, stages);
  LeadSearch search(graph);
  const int start = graph.id(p.decomposition.locate(p.world.robot.start), p.task.dfa.start);
  const int horizon = 0;
  graph.add_motion(start, 0);
  const std::vector<int> first = search.next(start, horizon);
  EXPECT_EQ(first, graph.lead(start, horizon));  // the first update searches the whole lead

  // A tree that has got into the second stage: nodes along the lead up to a few states into it.
  const auto second = std::find_if(first.begin(), first.end(),
                                   [&](int s) { return graph.stage_of(s) != p.task.dfa.start; });
  ASSERT_NE(second, first.end());
  const long entry = second - first.begin();
  for (long i = 1; i <= entry + 2; ++i) graph.add_motion(first[static_cast<size_t>(i)], static_cast<int>(i));
  const std::vector<int> whole = search.next(start, horizon);
  expect_product_path(p, stages, graph, whole, horizon);

  // Choosing the frontier's states over and over makes them dear: the next updates route around them,
  // keep the part before the frontier as it was, and stay paths of the product graph.
  for (int round = 0; round < 5; ++round) {
    for (size_t i = static_cast<size_t>(entry) + 1; i < whole.size(); ++i) {
      for (int k = 0; k < 50; ++k) graph.count_selection(whole[i]);
    }
    const std::vector<int> lead = search.next(start, horizon);
    expect_product_path(p, stages, graph, lead, horizon);
    EXPECT_TRUE(std::equal(whole.begin(), whole.begin() + entry + 1, lead.begin())) << round;
  }
}

TEST(LeadSearch, AMovedHorizonSearchesTheWholeLeadAgain) {
  const TestProblem p("ordered.lua");
  const StageGraph stages(p.task);
  ProductGraph graph(p.decomposition, stages);
  LeadSearch search(graph);
  const int start = graph.id(p.decomposition.locate(p.world.robot.start), p.task.dfa.start);
  graph.add_motion(start, 0);
  search.next(start, 2);
  EXPECT_EQ(search.next(start, 1), graph.lead(start, 1));
}

}  // namespace
}  // namespace physltl::planning
