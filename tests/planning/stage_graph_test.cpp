// The stages of a task about where bodies must be (BODY@REGION).

#include "physltl/planning/stage_graph.h"

#include "prepared_scenario.h"

#include <gtest/gtest.h>

namespace physltl::planning {
namespace {

TEST(StageGraph, ABodyMoveComesFirstAndABodyNoLongerNeededIsForgotten) {
  const PreparedScenario p("delivery.lua");  // F(crate@dock & F charger)
  const StageGraph stages(p.task);
  const int start = stages.stage(p.task.start_state(scenario::EnvironmentState::initial(p.world)), 0);
  EXPECT_EQ(stages.distance(start), 2);  // push the crate in, then go to the charger
  ASSERT_TRUE(stages.body_move(start));
  EXPECT_EQ(stages.body_move(start)->place, 1);  // into its first (only) named region, the dock
  // With the crate in the dock the task is about the charger only: wherever the crate goes next, the stage
  // is the same, and the robot moves next.
  const int docked = stages.after_letter(start, p.task.labelling.letter(1, -1));
  EXPECT_EQ(stages.distance(docked), 1);
  EXPECT_FALSE(stages.body_move(docked));
  EXPECT_EQ(stages.after_letter(docked, p.task.labelling.letter(0, -1)), docked);
}

TEST(StageGraph, ABodyThatMustStayPutKillsTheTaskWhenItLeaves) {
  const PreparedScenario p("sorting.lua");  // ... & G B3@shelf
  const StageGraph stages(p.task);
  const knowledge::Labelling& labels = p.task.labelling;
  const int start = stages.stage(p.task.start_state(scenario::EnvironmentState::initial(p.world)), 0);
  int b3 = -1;
  for (size_t i = 0; i < labels.named_parts().size(); ++i) {
    if (p.world.movable_bodies[static_cast<size_t>(labels.named_parts()[i].bodies.front())].name == "B3") b3 = static_cast<int>(i);
  }
  ASSERT_GE(b3, 0);
  const int facts = labels.facts_of(labels.letter(scenario::EnvironmentState::initial(p.world)));
  const int off_the_shelf = stages.after_letter(start, labels.letter(labels.with_place(facts, b3, 0), -1));
  EXPECT_TRUE(stages.dead(stages.automaton_state_of(off_the_shelf)));
  EXPECT_FALSE(stages.dead(stages.automaton_state_of(start)));
}

}  // namespace
}  // namespace physltl::planning
