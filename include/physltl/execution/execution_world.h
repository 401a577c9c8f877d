#pragma once
// What the executor drives: a world that executes controls and returns the state. Today a perturbed
// simulation stands in for reality; a real robot would implement the same two calls (docs/robustness.md).

#include "physltl/physics/simulation.h"
#include "physltl/scenario/state.h"
#include "physltl/scenario/world.h"

#include <vector>

namespace physltl::execution {

class ExecutionWorld {
 public:
  virtual ~ExecutionWorld() = default;
  // Applies the drive set-point for one physics step of the model's step_size.
  virtual void step(const scenario::Vec2& setpoint) = 0;
  // Where the robot and the bodies are now, and how fast they move.
  virtual scenario::EnvironmentState observe() const = 0;
};

// The stand-in for reality: ODE on a World (a perturbed one: what the executor does not know).
class SimulatedWorld : public ExecutionWorld {
 public:
  explicit SimulatedWorld(const scenario::World& truth) : simulation_(truth) {}
  void step(const scenario::Vec2& setpoint) override { simulation_.step(setpoint, contacts_); }
  scenario::EnvironmentState observe() const override { return simulation_.environment(); }

 private:
  physics::Simulation simulation_;
  std::vector<scenario::RobotContact> contacts_;
};

}  // namespace physltl::execution
