// Tasks about where bodies must be (BODY@REGION): the stages, the planner and the replay.

#include "physltl/planners/registry.h"
#include "physltl/planning/validation/replay.h"
#include "physltl/planning/stage_graph.h"

#include "test_problem.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace physltl::planning {
namespace {

// The step of the replay at which `fact` first holds; -1 never.
long first_step_with(const TestProblem& p, const Replay& r, const std::string& fact) {
  for (size_t i = 0; i < r.facts_trace.size(); ++i) {
    const std::vector<std::string> facts = p.original.labelling.object_facts(r.facts_trace[i]);
    if (std::ranges::find(facts, fact) != facts.end()) return static_cast<long>(i);
  }
  return -1;
}

TEST(Labelling, ALetterIsTheRobotsRegionAndWhereEachNamedBodyIs) {
  const TestProblem p("sorting.lua");
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
  const TestProblem p("../tests/data/crates_to_docks.lua");
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

TEST(ObjectTask, TheKnowledgePlannerPutsEveryBodyOfAGroupInSomeRegionOfItsSetAndTheReplayAgrees) {
  const TestProblem p("../tests/data/crates_to_docks.lua");
  const PlanResult result = p.solve(1);
  ASSERT_TRUE(result.solved) << result.stop_reason;
  const Replay r = p.check(result.plan);
  ASSERT_TRUE(r.validated()) << r.failure;
  EXPECT_GE(first_step_with(p, r, "crates@docks"), 0);
  for (const auto& pose : r.states.back().movable_poses) EXPECT_GT(pose.position.x(), 5.6);
}

TEST(StageGraph, ABodyMoveComesFirstAndABodyNoLongerNeededIsForgotten) {
  const TestProblem p("delivery.lua");  // F(crate@dock & F charger)
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
  const TestProblem p("sorting.lua");  // ... & G B3@shelf
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

TEST(ObjectTask, TheKnowledgePlannerSortsTheBoxesAndTheReplayValidatesIt) {
  const TestProblem p("sorting.lua");
  const PlanResult result = p.solve(1);
  ASSERT_TRUE(result.solved) << result.stop_reason;
  const Replay r = p.check(result.plan);
  ASSERT_TRUE(r.validated()) << r.failure;
  const long b1 = first_step_with(p, r, "B1@bay1"), b2 = first_step_with(p, r, "B2@bay2");
  ASSERT_GE(b1, 0);
  EXPECT_GT(b2, b1);
  // B3 never left its shelf, and everything ends at rest.
  for (int facts : r.facts_trace) {
    const std::vector<std::string> held = p.original.labelling.object_facts(facts);
    EXPECT_NE(std::ranges::find(held, "B3@shelf"), held.end());
  }
  EXPECT_TRUE(r.states.back().at_rest());
}

TEST(ObjectTask, TheSameSeedGivesTheSamePlanAndAnotherSeedAnother) {
  const TestProblem p("delivery.lua");
  const PlanResult a = p.solve(2), b = p.solve(2), c = p.solve(3);
  ASSERT_TRUE(a.solved && b.solved && c.solved);
  ASSERT_EQ(a.plan.controls.size(), b.plan.controls.size());
  for (size_t i = 0; i < a.plan.controls.size(); ++i) {
    EXPECT_EQ(a.plan.controls[i].setpoint, b.plan.controls[i].setpoint);
    EXPECT_EQ(a.plan.states[i], b.plan.states[i]);
  }
  EXPECT_NE(a.stats.propagations, c.stats.propagations);
}

TEST(ObjectTask, AStageWhoseOnlyNodeCannotGrowDoesNotHoldTheSearch) {
  // On these seeds the first node to put B1 in its bay stood against B1 just as INFERENCE switched that
  // side off, so every motion from it touched B1 from a forbidden side at its first step; it was the only
  // node of the stage, and the search grew from it until the time limit.
  const TestProblem p("sorting.lua");
  for (const std::uint64_t seed : {28u, 37u}) {
    const PlanResult result = p.solve(seed);
    ASSERT_TRUE(result.solved) << "seed " << seed << ": " << result.stop_reason;
    EXPECT_LT(result.stats.propagations, 50'000) << "seed " << seed;
    EXPECT_TRUE(p.check(result.plan).validated()) << "seed " << seed;
  }
}

TEST(ObjectTask, BrakingLongerThanOneControlEndsThePlanInSeveral) {
  const TestProblem p("../tests/data/slow_stop.lua");  // a sliding crate, controls of <= 6 steps
  const PlanResult result = p.solve(1);
  ASSERT_TRUE(result.solved) << result.stop_reason;
  const auto& controls = result.plan.controls;
  for (const Control& c : controls) EXPECT_LE(c.steps, p.world.planner.max_steps);
  ASSERT_GE(controls.size(), 2u);
  EXPECT_EQ(controls.back().setpoint, Vec2::Zero());
  EXPECT_EQ(controls[controls.size() - 2].setpoint, Vec2::Zero());  // the braking took more than one
  const Replay r = p.check(result.plan);
  EXPECT_TRUE(r.validated()) << r.failure;
  EXPECT_TRUE(r.states.back().at_rest());
}

TEST(Replay, APlanCutBeforeTheCrateReachesTheDockIsRejected) {
  const TestProblem p("delivery.lua");
  PlanResult result = p.solve(1);
  ASSERT_TRUE(result.solved) << result.stop_reason;
  const Replay whole = p.check(result.plan);
  ASSERT_TRUE(whole.validated()) << whole.failure;
  const long docked = first_step_with(p, whole, "crate@dock");
  ASSERT_GT(docked, 0);
  // Keep the controls that end before the crate's centre gets into the dock.
  long steps = 0;
  size_t keep = 0;
  while (keep < result.plan.controls.size() && steps + result.plan.controls[keep].steps < docked) steps += result.plan.controls[keep++].steps;
  result.plan.controls.resize(keep);
  result.plan.states.resize(keep);
  const Replay cut = p.check(result.plan);
  EXPECT_EQ(first_step_with(p, cut, "crate@dock"), -1);
  EXPECT_FALSE(cut.accepted);
  EXPECT_EQ(cut.failure, "the trace of regions and body facts does not satisfy the formula");
}

// `F G crate@dock` asks that the crate stays: a plan that pushes it through the dock and out, then
// stops, is rejected although the crate was in the dock on the way.
TEST(Replay, AStayTaskWhoseCrateEndsOutsideTheDockIsRejected) {
  const TestProblem reach("delivery.lua", {{"task", "F crate@dock"}});
  PlanResult result = reach.solve(1);
  ASSERT_TRUE(result.solved) << result.stop_reason;
  // The crate came into the dock from the doorway north of it, the robot behind it: push on south.
  result.plan.controls.push_back({Vec2(0.0, -0.9), 30});  // on, through and out of the dock
  result.plan.controls.push_back({Vec2::Zero(), 30});     // and stop
  result.plan.states.clear();                             // states not checked here: only the trace
  const TestProblem stay("delivery.lua", {{"task", "F G crate@dock"}});
  const Replay r = replay(stay.world, result.plan, stay.original, stay.knowledge);
  ASSERT_GE(first_step_with(stay, r, "crate@dock"), 0);  // it was there
  EXPECT_TRUE(stay.original.labelling.object_facts(r.facts_trace.back()).empty());  // and left
  EXPECT_FALSE(r.accepted);
  const Replay through = replay(reach.world, result.plan, reach.original, reach.knowledge);
  EXPECT_TRUE(through.accepted);  // while "at some time" holds
}

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
