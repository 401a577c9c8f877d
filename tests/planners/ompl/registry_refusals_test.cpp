// The program's registry refuses OMPL's LTLPlanner tasks about bodies and names why; the others take them.

#include "physltl/planners/registry.h"

#include "test_problem.h"

#include <gtest/gtest.h>

namespace physltl::planning {
namespace {

TEST(Planner, LtlPlannerRefusesTasksAboutBodiesAndSaysWhyWhileOmplsControlPlannersTakeThem) {
  const TestProblem p("delivery.lua");
  const auto why = planners::registry().refusal(planner_named("ompl-ltl"), p.task);
  ASSERT_TRUE(why);
  EXPECT_NE(why->find("BODY@REGION"), std::string::npos) << *why;
  EXPECT_FALSE(planners::registry().refusal(planner_named("ompl-rrt"), p.task));
  EXPECT_FALSE(planners::registry().refusal(planner_named("knowledge"), p.task));
  EXPECT_FALSE(planners::registry().refusal(planner_named("baseline"), p.task));
}

}  // namespace
}  // namespace physltl::planning
