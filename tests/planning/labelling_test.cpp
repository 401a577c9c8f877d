// The labelling of states as the task's letters: the robot's region and where each named body is.

#include "physltl/planning/task.h"

#include "prepared_scenario.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace physltl::planning {
namespace {

TEST(Labelling, ALetterIsTheRobotsRegionAndWhereEachNamedBodyIs) {
  const PreparedScenario p("sorting.lua");
  const knowledge::Labelling& labels = p.original.labelling;
  ASSERT_EQ(labels.named_parts().size(), 3u);  // B1, B2, B3, each with one region
  EXPECT_EQ(labels.fact_sets(), 8);
  scenario::EnvironmentState state = scenario::EnvironmentState::initial(p.world);
  EXPECT_EQ(labels.object_facts(labels.facts(state)), std::vector<std::string>{"B3@shelf"});
  state.movable_poses[0].position = {-2.8, 2.2};  // B1 into bay 1
  state.robot_position = {-0.6, 2.2};            // the robot in bay 2: the robot's region, not B2's
  const int letter = labels.letter(state);
  EXPECT_EQ(p.world.regions[static_cast<size_t>(labels.robot_region_of(letter))].name, "bay2");
  EXPECT_EQ(labels.object_facts(labels.facts_of(letter)), (std::vector<std::string>{"B1@bay1", "B3@shelf"}));
}

// crates@docks: one part of three bodies and two places, whatever the number of crates and docks; it
// holds only when every crate is in some dock, each in its own or two in one.
TEST(Labelling, AGroupIsOnePartThatHoldsWhenEveryBodyOfItIsInSomeRegionOfTheSet) {
  const PreparedScenario p("../tests/data/crates_to_docks.lua");
  const knowledge::Labelling& labels = p.original.labelling;
  ASSERT_EQ(labels.named_parts().size(), 1u);
  EXPECT_EQ(labels.named_parts()[0].bodies, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(labels.fact_sets(), 2);
  scenario::EnvironmentState state = scenario::EnvironmentState::initial(p.world);
  const auto holds = [&] { return labels.object_facts(labels.facts(state)) == std::vector<std::string>{"crates@docks"}; };
  EXPECT_FALSE(holds());
  state.movable_poses[0].position = {6.0, 4.5};  // C1 in dock3
  state.movable_poses[1].position = {6.0, 1.5};  // C2 in dock1
  EXPECT_FALSE(holds());                          // C3 still out
  state.movable_poses[2].position = {6.1, 3.0};  // C3 in dock2
  EXPECT_TRUE(holds());
  state.movable_poses[2].position = {6.0, 5.2};  // C3 just past dock3's edge
  EXPECT_FALSE(holds());
}

}  // namespace
}  // namespace physltl::planning
