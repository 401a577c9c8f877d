#include "product_graph.h"

#include "product_path.h"
#include "test_problem.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace physltl::planning {
namespace {

using namespace physltl::planners::knowledge;

TEST(ProductGraph, TheLeadWalksNeighbouringTrianglesToAcceptance) {
  const TestProblem p("ordered.lua");
  const StageGraph stages(p.task);
  ProductGraph graph(p.decomposition, stages);
  const int start_triangle = p.decomposition.locate(p.world.robot.start);
  const int start = graph.id(start_triangle, p.task.start_state(scenario::EnvironmentState::initial(p.world)));
  const std::vector<int> lead = graph.lead(start);
  ASSERT_GE(lead.size(), 2u);
  EXPECT_EQ(lead.front(), start);
  EXPECT_TRUE(p.task.dfa.accepting[static_cast<size_t>(stages.automaton_state_of(graph.stage_of(lead.back())))]);
  expect_product_path(p, stages, graph, lead, 0);
}

TEST(ProductGraph, ALeadWithAHorizonStopsAtTheFirstStateThatClose) {
  const TestProblem p("ordered.lua");  // four regions in order: the start is four steps from acceptance
  const StageGraph stages(p.task);
  ProductGraph graph(p.decomposition, stages);
  const int start = graph.id(p.decomposition.locate(p.world.robot.start), p.task.dfa.start);
  ASSERT_EQ(stages.distance(p.task.dfa.start), 4);
  const std::vector<int> full = graph.lead(start);
  for (int horizon = 3; horizon >= 1; --horizon) {
    const std::vector<int> lead = graph.lead(start, horizon);
    expect_product_path(p, stages, graph, lead, horizon);
    ASSERT_FALSE(lead.empty());
    EXPECT_EQ(stages.distance(graph.stage_of(lead.back())), horizon);
    EXPECT_LT(lead.size(), full.size());
  }
}

TEST(ProductGraph, DroppingAStatesLastNodeMakesItUnexploredAgain) {
  const TestProblem p("ordered.lua");
  const StageGraph stages(p.task);
  ProductGraph graph(p.decomposition, stages);
  const int state = graph.id(0, p.task.dfa.start);
  const double unexplored = graph.weight(state);
  graph.add_motion(state, 7);
  graph.add_motion(state, 9);
  EXPECT_GT(graph.weight(state), unexplored);
  graph.remove_motion(state, 7);
  EXPECT_EQ(graph.motions(state), std::vector<int>{9});
  graph.remove_motion(state, 9);
  EXPECT_TRUE(graph.motions(state).empty());
  EXPECT_EQ(graph.weight(state), unexplored);
}

}  // namespace
}  // namespace physltl::planning
