#pragma once
// What every lead must be: a path of the product graph that ends within its horizon.

#include "product_graph.h"
#include "test_problem.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace physltl::planning {

// Neighbouring triangles, each entered with the stage's step on its region; only the last state is within
// `horizon` moves of acceptance.
inline void expect_product_path(const TestProblem& p, const StageGraph& stages, const planners::knowledge::ProductGraph& graph,
                                const std::vector<int>& lead, int horizon) {
  ASSERT_FALSE(lead.empty());
  EXPECT_LE(stages.distance(graph.stage_of(lead.back())), horizon);
  for (size_t i = 1; i < lead.size(); ++i) {
    const auto& from = p.decomposition.triangles()[graph.triangle_of(lead[i - 1])];
    const int to = graph.triangle_of(lead[i]);
    ASSERT_NE(std::find(from.neighbors.begin(), from.neighbors.end(), to), from.neighbors.end()) << i;
    ASSERT_EQ(graph.stage_of(lead[i]), stages.after_robot(graph.stage_of(lead[i - 1]), p.decomposition.triangles()[to].region));
    EXPECT_GT(stages.distance(graph.stage_of(lead[i - 1])), horizon);
  }
}

}  // namespace physltl::planning
