#pragma once
// The state OMPL's planners search: the full physics state (exact, so a propagation from a stored state is
// reproducible), two flags about the step that made it, and on our product the task automaton's state;
// with distances, sampling and a projection on the robot's pose.

#include "seeds.h"

#include "physltl/planning/stage_graph.h"

#include "physltl/physics/simulation.h"
#include "physltl/planning/task.h"
#include "physltl/scenario/world.h"

#include <ompl/base/ProjectionEvaluator.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/control/Control.h>

#include <vector>

namespace physltl::planners::ompl {

namespace ob = ::ompl::base;
namespace oc = ::ompl::control;
using scenario::Vec2;

// After the physics values: the step passed the validity checker; it took the robot into a triangle OMPL's
// product graph does not connect to the one it left (step_neighbours in decomposition.h); and on our
// product, the automaton state after it.
enum Flag : std::size_t { kValid = 0, kBeyondGraph = 1, kAutomatonState = 2 };

// A distance between automaton states, in metres of robot motion: nearer states in another automaton
// state never stand in for one in this one (SST's pruning, the nearest neighbours of RRT).
inline constexpr double kAutomatonStateWeight = 100.0;

// Our product's automaton: the task's, with its stages (whose dead automaton states no step may enter).
// The bodies the task names are part of the product too: where they stand counts in distances, samples
// and KPIECE1's and PDST's grid as the robot's position does, or nothing would lead a search to move them.
struct TaskProduct {
  explicit TaskProduct(const planning::TaskAutomaton& task);
  const planning::TaskAutomaton& task;
  planning::StageGraph stages;
  std::vector<int> live;  // the automaton states that are not dead, which the state sampler draws from
  std::vector<std::size_t> named_values;  // where each named body's x, y are in the physics values
};

class PhysicsSpace : public ob::RealVectorStateSpace {
 public:
  // `product`: our product's automaton, carried in the state; null on OMPL's product, which adds the
  // automaton state as a space of its own.
  PhysicsSpace(const scenario::World& world, const physics::PhysicsState& start, SeedSequence& seeds,
               const TaskProduct* product);

  std::size_t values() const { return values_; }
  const std::vector<double>& start_values() const { return start_; }
  bool differential() const { return differential_; }
  const scenario::World& world() const { return world_; }
  const TaskProduct* product() const { return product_; }

  // The robot's pose: position in metres, and a differential robot's heading at a quarter metre a radian;
  // on our product kAutomatonStateWeight more between two automaton states.
  double distance(const ob::State* a, const ob::State* b) const override;

  ob::StateSamplerPtr allocDefaultStateSampler() const override;
  void registerProjections() override;

 private:
  SeedSequence& seeds_;
  const scenario::World& world_;
  const bool differential_;
  const std::size_t values_;
  const TaskProduct* product_;
  std::vector<double> start_ = std::vector<double>(values_);
};

// The values of a state of the physics space, or of OMPL's product over it (`compound`).
const double* physics_values(const ob::State* state, bool compound);
double* physics_values(ob::State* state, bool compound);

// The robot's position, in cells of 1/20 of the workspace (OMPL's default share of the extent), and the
// automaton state as a third coordinate on either product, so cells never mix automaton states: KPIECE1's
// and PDST's grid.
class RobotPosition : public ob::ProjectionEvaluator {
 public:
  // `automaton_states`: 0 for the robot's own space; `ompl_product`: the state is OMPL's product's, else
  // the automaton state is the flag after the `values` physics values.
  RobotPosition(const ob::StateSpace* space, const scenario::World& world, int automaton_states, bool ompl_product,
                std::size_t values);
  // On our product, with the named bodies' positions after the automaton state.
  RobotPosition(const ob::StateSpace* space, const scenario::World& world, const TaskProduct& product, std::size_t values);
  unsigned int getDimension() const override {
    return (automaton_states_ > 0 ? 3 : 2) + 2 * static_cast<unsigned>(named_values_.size());
  }
  void project(const ob::State* state, Eigen::Ref<Eigen::VectorXd> out) const override;

 private:
  void set_grid(const scenario::World& world);
  const int automaton_states_;
  std::vector<std::size_t> named_values_;
  const bool ompl_product_;
  const std::size_t values_;
};

// A control is a set-point: a holonomic robot's (speed, heading), a differential robot's (forward speed,
// turn rate). Both ways:
geometry::Vec2 setpoint_of(const oc::Control* control, bool differential);
void set_control(oc::Control* control, const geometry::Vec2& setpoint, bool differential);

}  // namespace physltl::planners::ompl
