// The run's deadline (base/deadline.h) around a planner's preparation, with a stub planner of the test's own.

#include "physltl/planning/planning_problem.h"

#include "prepared_scenario.h"
#include "stub_planner.h"

#include <gtest/gtest.h>

#include <memory>

namespace physltl::planning {
namespace {

// A run whose preparation the deadline cut short asks for it again to search; with the deadline past, no
// preparation starts (its first steps check no deadline: a 16-box task's stage graph took a second).
TEST(Deadline, APreparationAskedForAfterTheDeadlineStartsNoWork) {
  const PreparedScenario p("rooms.lua");
  const PlanningProblem problem(p.world);
  PlannerEntry counting = stub_planner();
  int preparations = 0;
  counting.prepare = [&](const Problem&, const PreparationOptions&) {
    ++preparations;
    return std::shared_ptr<const PlannerData>();
  };
  EXPECT_THROW(problem.preparation(counting, {base::Deadline::in(0.0)}), base::DeadlineReached);
  EXPECT_EQ(preparations, 0);
  EXPECT_EQ(problem.preparation(counting, {}), nullptr);
  EXPECT_EQ(preparations, 1);
}

}  // namespace
}  // namespace physltl::planning
