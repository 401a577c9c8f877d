// Execution with monitoring and replanning, in perturbed simulations standing in for reality.

#include "physltl/execution/executor.h"
#include "physltl/execution/replanner.h"
#include "physltl/execution/perturbation.h"
#include "physltl/execution/robustness.h"
#include "test_problem.h"

#include <gtest/gtest.h>

namespace executor_test {

using namespace physltl;
using namespace physltl::planning;
using namespace physltl::execution;

// The remaining task planned in the model from here, as execute replans.
execution::Replanned replan(const scenario::World& from_here) {
  PlannerOptions options;
  options.seed = 5;
  return execution::replan(from_here, planners::registry().default_planner(), options, 200'000);
}

class Executing : public OrderedPlanPushingBoxes {
 protected:
  execution::Execution run_in(const scenario::World& truth, const execution::ExecutionOptions& options = {}) const {
    execution::SimulatedWorld reality(truth);
    return execution::Executor(problem_.world, problem_.original, result_.plan, nominal_, options).run(reality, replan);
  }

  // The executed controls replayed from the truth's start: the same run, bit for bit, judged as robustness is.
  void expect_replay_reproduces(const scenario::World& truth, const execution::Execution& run, bool succeeds) const {
    const Plan executed{run.controls, {}};
    const Replay again = replay(truth, executed, problem_.original, knowledge::formulate(truth));
    ASSERT_EQ(again.states.size(), run.states.size());
    for (size_t i = 0; i < run.states.size(); ++i) {
      ASSERT_EQ(again.states[i].robot_position, run.states[i].robot_position) << "step " << i;
      for (size_t b = 0; b < truth.movable_bodies.size(); ++b) {
        ASSERT_EQ(again.states[i].movable_poses[b].position, run.states[i].movable_poses[b].position) << "step " << i;
        ASSERT_EQ(again.states[i].movable_poses[b].yaw, run.states[i].movable_poses[b].yaw) << "step " << i;
      }
    }
    EXPECT_EQ(judge_in_world(truth, executed, nullptr, problem_.original).succeeded, succeeds);
    if (succeeds) {
      EXPECT_TRUE(again.accepted) << again.failure;
    }
  }

};

TEST_F(Executing, TheModelItselfNeedsNoReplanningAndRunsThePlanAsPlanned) {
  const execution::Execution run = run_in(problem_.world);
  EXPECT_EQ(run.replans, 0);
  EXPECT_EQ(run.stopped, "");
  EXPECT_EQ(run.steps, result_.plan.total_steps());
  ASSERT_EQ(run.controls.size(), result_.plan.controls.size());
  for (size_t c = 0; c < run.controls.size(); ++c) {
    EXPECT_EQ(run.controls[c].setpoint, result_.plan.controls[c].setpoint);
    EXPECT_EQ(run.controls[c].steps, result_.plan.controls[c].steps);
  }
  expect_replay_reproduces(problem_.world, run, true);
}

TEST_F(Executing, ABoxThreeTimesHeavierThanModelledFailsOpenLoopAndSucceedsWithReplanning) {
  scenario::World truth = problem_.world;
  truth.movable_bodies[static_cast<size_t>(nominal_.moved_bodies.front())].mass *= 3;
  ASSERT_FALSE(judge_in_world(truth, result_.plan, &nominal_, problem_.original).succeeded);
  // Every replanning plans in the model, with the box a third of its true mass, so each plan deviates
  // again; this plan takes 9 of them to get there, more than the default 5.
  const execution::Execution run = run_in(truth, {.max_replans = 10});
  EXPECT_GE(run.replans, 1);
  EXPECT_EQ(run.stopped, "");
  EXPECT_GT(run.planning_propagations, 0);
  expect_replay_reproduces(truth, run, true);
}

TEST_F(Executing, PerturbedWorldsReproduceTheirRunsAndTheSameSeedTheSameExecution) {
  scenario::Uncertainty u;
  u.mass = 0.2;
  u.friction = 0.2;
  u.start = 0.02;
  int succeeded = 0;
  for (int i = 0; i < 6; ++i) {
    const scenario::World truth = perturbed_world(problem_.world, u, 9, i);
    const execution::Execution run = run_in(truth);
    const bool ok = judge_in_world(truth, Plan{run.controls, {}}, nullptr, problem_.original).succeeded;
    succeeded += ok;
    expect_replay_reproduces(truth, run, ok);
    const execution::Execution again = run_in(truth);
    ASSERT_EQ(again.controls.size(), run.controls.size()) << "world " << i;
    EXPECT_EQ(again.steps, run.steps);
    EXPECT_EQ(again.replans, run.replans);
  }
  EXPECT_GE(succeeded, 5);
}

TEST(WorldFromState, PutsTheRobotAndTheBodiesWhereTheStateHasThemWithTheRemainingTask) {
  const TestProblem p("ordered.lua");
  scenario::EnvironmentState state = scenario::EnvironmentState::initial(p.world);
  state.robot_position += scenario::Vec2(0.1, -0.2);
  state.movable_poses[0].position += scenario::Vec2(0.3, 0.0);
  state.movable_poses[0].yaw = 0.2;
  const scenario::World here = execution::world_from_state(p.world, state, ltl::parse("F p2"));
  EXPECT_EQ(here.robot.start, state.robot_position);
  EXPECT_EQ(here.movable_bodies[0].footprint.pose.position, state.movable_poses[0].position);
  EXPECT_EQ(here.movable_bodies[0].footprint.pose.yaw, 0.2);
  EXPECT_EQ(here.task.formula, "F p2");
  EXPECT_EQ(here.fixed_bodies.size(), p.world.fixed_bodies.size());
}

}  // namespace executor_test
