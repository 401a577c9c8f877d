// What replay counts as a push (count_pushes, replay.h): what `--cost pushes`, `expect { max_pushes }` and
// every report's "pushes" mean.

#include "prepared_scenario.h"

#include "physltl/planning/validation/replay.h"

#include <gtest/gtest.h>

#include <vector>

namespace physltl::planning {
namespace {

// A trace of one body, built a step at a time: whether the robot touched a body during the step, and how
// far the body moved along x in it.
struct Trace {
  scenario::StateTrace states;
  std::vector<bool> pushing{false};
  scenario::EnvironmentState state;
  Trace() {
    state.movable_poses = {geometry::Pose2{Vec2::Zero(), 0.0}};
    state.movable_velocities = {Vec2::Zero()};
    states = scenario::StateTrace(state);
  }
  void steps(int n, bool touching, double metres_each) {
    for (int i = 0; i < n; ++i) {
      state.movable_poses[0].position.x() += metres_each;
      states.push_back(state);
      pushing.push_back(touching);
    }
  }
  int pushes() const { return count_pushes(states, pushing, 0.05); }
};

TEST(PushCount, ContactLostForAMomentIsOnePushAndABrushThatMovesNothingIsNone) {
  Trace t;
  t.steps(10, true, 0.01);   // pushed 10 cm
  t.steps(4, false, 0.0);    // 0.2 s without contact: the box ran ahead
  t.steps(3, true, 0.01);    // the same push goes on
  t.steps(20, false, 0.0);
  t.steps(5, true, 0.0);     // the robot grazes the box: it does not move
  t.steps(5, false, 0.0);
  EXPECT_EQ(t.pushes(), 1);
  t.steps(6, false, 0.0);    // well apart from the last touch: another push
  t.steps(2, true, 0.01);
  EXPECT_EQ(t.pushes(), 2);
}

TEST(PushCount, AKnockThatSendsTheBodySlidingIsAPush) {
  Trace t;
  t.steps(1, true, 0.004);   // a touch of one step, 4 mm in it
  t.steps(10, false, 0.003); // then it slides 3 cm on
  EXPECT_EQ(t.pushes(), 1);
}

// wall_and_box.lua: the robot drives north into the box in controls of 4 steps, pushing it about 0.6 m
// in one go. A push is what a person sees, not how the plan cuts its controls.
TEST(PushCount, OnePushOverManyControlsCountsOnceAndTwoApartCountTwice) {
  PreparedScenario p("../tests/data/wall_and_box.lua");
  const auto drive = [](Plan& plan, Vec2 velocity, int steps) {
    for (; steps > 0; steps -= 4) plan.controls.push_back({velocity, std::min(steps, 4)});
  };
  Plan once;
  drive(once, {0.0, 1.0}, 28);
  const Replay one = replay(p.world, once, p.original, p.knowledge, {.record_control_states = true});
  EXPECT_EQ(one.pushes, 1);
  EXPECT_FALSE(one.moved_bodies.empty());
  Plan twice = once;
  drive(twice, {0.0, -1.0}, 10);  // back off half a metre
  drive(twice, {0.0, 1.0}, 16);   // and push again
  const Replay two = replay(p.world, twice, p.original, p.knowledge, {.record_control_states = true});
  EXPECT_EQ(two.pushes, 2);
}

}  // namespace
}  // namespace physltl::planning
