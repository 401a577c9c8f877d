#pragma once
// A plan: controls applied from the World's initial state, and what replaying them showed.

#include "physltl/physics/simulation.h"
#include "physltl/scenario/world.h"

#include <string>
#include <vector>

namespace physltl::planning {

using scenario::Vec2;

// A constant drive set-point for a number of physics steps: (vx, vy) in m/s for a holonomic robot,
// (forward speed m/s, turn rate rad/s) for a differential one (physics::Simulation::step).
struct Control {
  Vec2 setpoint = Vec2::Zero();
  int steps = 1;
};

struct Plan {
  std::vector<Control> controls;
  // The physics state after each control, as the planner saw it; replay must reproduce them exactly.
  std::vector<physics::PhysicsState> states;
  int total_steps() const {
    int total = 0;
    for (const auto& c : controls) total += c.steps;
    return total;
  }
};

// One edge of the search tree, for pictures: where the robot went and in which automaton state it ended.
struct TreeEdge {
  Vec2 from = Vec2::Zero();
  Vec2 to = Vec2::Zero();
  int automaton_state = 0;
};

}  // namespace physltl::planning
