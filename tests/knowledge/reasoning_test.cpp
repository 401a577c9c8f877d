// reason_about on the paper's worlds and on one whose only goal is walled off.

#include "physltl/knowledge/reasoning.h"

#include "physltl/scenario/load.h"

#include <gtest/gtest.h>

#include <map>
#include <string>

namespace physltl::knowledge {
namespace {

knowledge::Reasoning reason_about_file(const std::string& relative_path, const std::map<std::string, std::string>& params = {}) {
  return knowledge::reason_about(scenario::load_scenario(std::string(PHYSLTL_SOURCE_DIR) + "/" + relative_path, {.params = params}));
}

TEST(ReasonAbout, RoomsDropsTheEnclosedP3AndPlansTheRest) {
  const knowledge::Reasoning r = reason_about_file("scenarios/rooms.lua");
  EXPECT_EQ(r.feasibility.invalid_names(), std::vector<std::string>{"p3"});
  ASSERT_TRUE(r.feasible());
  ASSERT_TRUE(r.simplified_formula());
  EXPECT_EQ(ltl::to_string(*r.simplified_formula()), "F(p1 & F(p2 & F p4))");
  ASSERT_TRUE(r.task.by_lists);
  EXPECT_EQ(ltl::to_string(*r.task.by_lists->formula), "F(p1 & F(p2 & F p4))");
  ASSERT_TRUE(r.task.dfa);
  EXPECT_EQ(r.task.dfa->propositions, (std::vector<std::string>{"p1", "p2", "p4"}));
  EXPECT_EQ(r.task.dfa->size(), 4u);
}

TEST(ReasonAbout, RoomsKappaZeroTypesTheDoorwayBoxesConstraintOriented) {
  const knowledge::Reasoning r = reason_about_file("scenarios/rooms.lua");
  ASSERT_EQ(r.initial_kappa.bodies.size(), 3u);
  for (const knowledge::BodyKappa& body : r.initial_kappa.bodies) {
    EXPECT_EQ(body.type, knowledge::BodyType::kConstraintOriented);
    EXPECT_FALSE(body.active_faces.contains(static_cast<int>(scenario::Side::kMinusX)));
    EXPECT_TRUE(body.active_faces.contains(static_cast<int>(scenario::Side::kPlusY)));
  }
  EXPECT_EQ(r.initial_state.robot_position, r.knowledge.robot.start);
}

TEST(ReasonAbout, WithNothingInvalidTheTaskIsItsNormalForm) {
  const knowledge::Reasoning r = reason_about_file("scenarios/ordered.lua");
  EXPECT_TRUE(r.feasibility.invalid.empty());
  EXPECT_FALSE(r.task.semantic);
  ASSERT_TRUE(r.simplified_formula());
  EXPECT_EQ(*r.simplified_formula(), r.task.normal_form);
  EXPECT_TRUE(r.task.dfa);
}

TEST(ReasonAbout, AnEnclosedOnlyGoalMakesTheTaskInfeasible) {
  const knowledge::Reasoning r = reason_about_file("tests/app/enclosed_goal.lua");
  EXPECT_FALSE(r.feasible());
  EXPECT_FALSE(r.simplified_formula());
  EXPECT_FALSE(r.task.dfa);
  ASSERT_EQ(r.feasibility.invalid.size(), 1u);
  EXPECT_EQ(r.feasibility.invalid[0].reason, "goal: region enclosed by fixed walls");
}

TEST(ReasonAbout, ATaskTheStartAlreadyLosesIsInfeasibleAndSaysWhereWhatStands) {
  const knowledge::Reasoning robot = reason_about_file("tests/app/starts_in_hazard.lua");
  EXPECT_FALSE(robot.feasible());
  EXPECT_FALSE(robot.task.dfa);
  EXPECT_EQ(robot.task.infeasibility(), "the start already rules it out: at the start the robot is in hazard");
  const knowledge::Reasoning box = reason_about_file("tests/app/starts_in_hazard.lua", {{"task", "box"}});
  EXPECT_FALSE(box.feasible());
  EXPECT_EQ(box.task.infeasibility(), "the start already rules it out: at the start crate is in aisle");
}

TEST(ReasonAbout, AStartThatKeepsTheTaskOpenLeavesItFeasible) {
  // Sorting: B3 starts on its shelf, which G B3@shelf asks for; rooms.lua: the robot starts in no region.
  EXPECT_TRUE(reason_about_file("scenarios/sorting.lua").feasible());
  EXPECT_TRUE(reason_about_file("scenarios/avoid.lua").feasible());
}

TEST(ReasonAbout, AnLShapedDeskMeshKeepsItsInnerCornerReachable) {
  // The corner region lies inside the rectangle round the desk, so a desk that collided as its bounds
  // would wall it off; the mesh collides as its L.
  const knowledge::Reasoning r = reason_about_file("tests/app/l_desk_corner.lua");
  EXPECT_TRUE(r.feasibility.invalid.empty()) << r.feasibility.invalid.front().reason;
  EXPECT_TRUE(r.feasible());
  const geometry::Footprint& desk = r.knowledge.fixed_bodies.at(0).footprint;
  EXPECT_TRUE(geometry::contains(desk.shape, desk.pose, {2.3, 3.2}));   // in the short bar
  EXPECT_FALSE(geometry::contains(desk.shape, desk.pose, {3.2, 3.2}));  // in the corner
  EXPECT_NEAR(desk.shape.area(), 2 * 0.6 + 0.6 * 0.9, 1e-6);
}

}  // namespace
}  // namespace physltl::knowledge
