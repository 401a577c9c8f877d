// Going round the movable bodies or pushing through them: the rule, stage by stage.

#include "route_choice.h"

#include "physltl/planning/stage_graph.h"
#include "test_problem.h"

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <utility>

namespace physltl::planning {
namespace {

using namespace physltl::planners::knowledge;

bool first_stage_goes_round(const std::string& scenario, const std::map<std::string, std::string>& params = {}) {
  const TestProblem p(scenario, params);
  const StageGraph stages(p.task);
  const scenario::EnvironmentState start = scenario::EnvironmentState::initial(p.world);
  return choose_routes(p.world, p.task, StageGraph(p.task), p.decomposition).going_round[static_cast<size_t>(
      stages.stage(p.task.start_state(start), p.task.labelling.facts(start)))];
}

TEST(RouteChoice, GoesRoundWhereTheWayRoundIsALittleLongerAndPushesWhereItIsMuchLongerOrNone) {
  EXPECT_TRUE(first_stage_goes_round("../tests/data/box_row.lua"));   // 11.5 m round, 8.5 m through
  EXPECT_FALSE(first_stage_goes_round("../tests/data/long_detour.lua"));  // 14.5 m round, 3 m through
  EXPECT_FALSE(first_stage_goes_round("../tests/data/through_a_box.lua"));  // no way round
  EXPECT_FALSE(first_stage_goes_round("rooms.lua"));  // B1 closes room 1's corridor
  EXPECT_TRUE(first_stage_goes_round("warehouse_rows.lua"));
}

TEST(RouteChoice, DoesNotGoRoundThroughARegionTheTaskForbidsThere) {
  // The only push-free way crosses the hazard band; the other way is a gap holding a box.
  const std::string world = "../tests/data/regression/hazard_gap.lua";
  EXPECT_FALSE(first_stage_goes_round(world));                                   // F goal & G !hazard
  EXPECT_FALSE(first_stage_goes_round(world, {{"task", "!hazard U goal"}}));
  EXPECT_TRUE(first_stage_goes_round(world, {{"task", "F goal"}}));              // the hazard is just floor
}

TEST(RouteChoice, AWayNarrowerThanTheMinimumFreeWidthIsNoWayRound) {
  const std::string sliver = "../tests/data/regression/narrow_sliver.lua";
  EXPECT_FALSE(first_stage_goes_round(sliver));                         // 5 cm for the robot's centre
  EXPECT_TRUE(first_stage_goes_round(sliver, {{"box_width", "0.3"}}));  // 20 cm
  // 8 cm of the goal free beside a box the robot starts against: the goal is reached by pushing.
  EXPECT_FALSE(first_stage_goes_round("../tests/data/regression/start_at_box.lua"));
}

TEST(RouteChoice, ARobotBrakedAHairIntoAWallStillPushesTheBoxThatClosesItsCorridor) {
  // ODE lets a robot pressed against a wall sink about a millimetre into it: its centre is then inside the
  // wall's grown outline, and the start must still count as a place with ways out of it.
  const TestProblem p("../tests/data/regression/start_at_wall.lua", {{"gap", "0"}});
  scenario::World world = p.world;
  world.robot.start += geometry::Vec2(0.2, 0.151);  // 1 mm into the corridor's north wall
  const StageGraph stages(p.task);
  const scenario::EnvironmentState start = scenario::EnvironmentState::initial(world);
  EXPECT_FALSE(choose_routes(world, p.task, StageGraph(p.task), p.decomposition)
                   .going_round[static_cast<size_t>(stages.stage(p.task.start_state(start), p.task.labelling.facts(start)))]);
}

TEST(RouteChoice, OnlyTheTrianglesUnderBodiesTheTaskDoesNotNameAreGoneRound) {
  const TestProblem p("delivery.lua");  // B1 in room 1's corridor; the crate is moved on purpose
  const std::vector<bool> under = triangles_under_bodies(p.world, p.task, p.decomposition);
  const auto triangle_at = [&](double x, double y) { return under[static_cast<size_t>(p.decomposition.locate({x, y}))]; };
  EXPECT_TRUE(triangle_at(-3.0, 1.7));   // B1
  EXPECT_FALSE(triangle_at(-3.5, 0.0));  // the crate
  EXPECT_FALSE(triangle_at(3.0, 0.0));   // the open hall
}

}  // namespace
}  // namespace physltl::planning
