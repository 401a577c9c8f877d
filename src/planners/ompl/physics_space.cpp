#include "physics_space.h"

#include <ompl/base/spaces/DiscreteStateSpace.h>
#include <ompl/control/spaces/RealVectorControlSpace.h>
#include <ompl/util/RandomNumbers.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace physltl::planners::ompl {

using geometry::Vec2;

namespace {

constexpr std::size_t kValuesPerBody = physics::PhysicsState::kValuesPerBody;

// Samples (what RRT, SST and PDST grow towards) a pose of the robot anywhere in the workspace, the rest as
// at the start, and on our product a live automaton state; its generator is seeded from the run's seed.
class RobotPoseSampler : public ob::StateSampler {
 public:
  RobotPoseSampler(const PhysicsSpace* space, std::uint_fast32_t seed) : ob::StateSampler(space), space_(space) {
    rng_.setLocalSeed(seed);
  }
  void sampleUniform(ob::State* state) override {
    const auto& w = space_->world();
    const double r = w.robot.radius;
    const double automaton_state = sampled_automaton_state();
    place(state, {rng_.uniformReal(w.workspace.bounds.min.x() + r, w.workspace.bounds.max.x() - r),
                  rng_.uniformReal(w.workspace.bounds.min.y() + r, w.workspace.bounds.max.y() - r)},
          rng_.uniformReal(-std::numbers::pi, std::numbers::pi), automaton_state);
    if (space_->product() == nullptr) return;
    double* v = state->as<PhysicsSpace::StateType>()->values;
    for (const std::size_t k : space_->product()->named_values) {
      v[k] = rng_.uniformReal(w.workspace.bounds.min.x(), w.workspace.bounds.max.x());
      v[k + 1] = rng_.uniformReal(w.workspace.bounds.min.y(), w.workspace.bounds.max.y());
    }
  }
  void sampleUniformNear(ob::State* state, const ob::State* near, double distance) override {
    const double* v = near->as<PhysicsSpace::StateType>()->values;
    place(state, {v[0] + rng_.uniformReal(-distance, distance), v[1] + rng_.uniformReal(-distance, distance)}, v[3],
          automaton_state_of(v));
    keep_named_bodies(state, v);
  }
  void sampleGaussian(ob::State* state, const ob::State* mean, double sigma) override {
    const double* v = mean->as<PhysicsSpace::StateType>()->values;
    place(state, {rng_.gaussian(v[0], sigma), rng_.gaussian(v[1], sigma)}, v[3], automaton_state_of(v));
    keep_named_bodies(state, v);
  }

 private:
  double sampled_automaton_state() {
    const TaskProduct* product = space_->product();
    if (product == nullptr) return 0.0;
    return product->live[static_cast<size_t>(rng_.uniformInt(0, static_cast<int>(product->live.size()) - 1))];
  }
  // A sample near another keeps its named bodies where they are there.
  void keep_named_bodies(ob::State* state, const double* near) const {
    if (space_->product() == nullptr) return;
    double* v = state->as<PhysicsSpace::StateType>()->values;
    for (const std::size_t k : space_->product()->named_values) v[k] = near[k], v[k + 1] = near[k + 1];
  }
  double automaton_state_of(const double* v) const { return space_->product() != nullptr ? v[space_->values() + kAutomatonState] : 0.0; }
  void place(ob::State* state, const Vec2& p, double yaw, double automaton_state) const {
    double* v = state->as<PhysicsSpace::StateType>()->values;
    std::copy(space_->start_values().begin(), space_->start_values().end(), v);
    v[0] = p.x(), v[1] = p.y();
    if (space_->differential()) v[3] = yaw;
    v[space_->values() + kValid] = 1.0;
    v[space_->values() + kBeyondGraph] = 0.0;
    if (space_->product() != nullptr) v[space_->values() + kAutomatonState] = automaton_state;
  }
  const PhysicsSpace* space_;
};

// The workspace's x and y as the first two dimensions of `bounds`.
void set_workspace_bounds(ob::RealVectorBounds& bounds, const scenario::World& world) {
  bounds.setLow(0, world.workspace.bounds.min.x()), bounds.setHigh(0, world.workspace.bounds.max.x());
  bounds.setLow(1, world.workspace.bounds.min.y()), bounds.setHigh(1, world.workspace.bounds.max.y());
}

}  // namespace

TaskProduct::TaskProduct(const planning::TaskAutomaton& automaton) : task(automaton), stages(automaton) {
  for (int q = 0; q < static_cast<int>(automaton.dfa.size()); ++q) {
    if (!stages.dead(q)) live.push_back(q);
  }
  // The robot is the physics state's first body, the movable bodies follow in World order.
  for (const auto& named : task.labelling.named_parts()) {
    for (int body : named.bodies) named_values.push_back(static_cast<std::size_t>(body + 1) * kValuesPerBody);
  }
}

PhysicsSpace::PhysicsSpace(const scenario::World& world, const physics::PhysicsState& start, SeedSequence& seeds,
                           const TaskProduct* product)
    : ob::RealVectorStateSpace(static_cast<unsigned>(start.bodies() * kValuesPerBody + (product != nullptr ? 3 : 2))),
      seeds_(seeds),
      world_(world),
      differential_(world.robot.drive == scenario::Drive::kDifferential),
      values_(start.bodies() * kValuesPerBody),
      product_(product) {
  start.copy_values(start_);
  setName("PhysicsState");
  ob::RealVectorBounds b(getDimension());
  const Vec2 lo = world.workspace.bounds.min, hi = world.workspace.bounds.max;
  for (std::size_t body = 0; body < start.bodies(); ++body) {
    const std::size_t k = body * kValuesPerBody;
    b.setLow(k, lo.x() - 1), b.setHigh(k, hi.x() + 1);
    b.setLow(k + 1, lo.y() - 1), b.setHigh(k + 1, hi.y() + 1);
    b.setLow(k + 2, -1), b.setHigh(k + 2, 1);
    b.setLow(k + 3, -2 * std::numbers::pi), b.setHigh(k + 3, 2 * std::numbers::pi);
    for (std::size_t v = 4; v < kValuesPerBody; ++v) b.setLow(k + v, -1e3), b.setHigh(k + v, 1e3);
  }
  b.setLow(values_ + kValid, 0), b.setHigh(values_ + kValid, 1);
  b.setLow(values_ + kBeyondGraph, 0), b.setHigh(values_ + kBeyondGraph, 1);
  if (product != nullptr) {
    b.setLow(values_ + kAutomatonState, 0), b.setHigh(values_ + kAutomatonState, static_cast<double>(product->task.dfa.size()));
  }
  setBounds(b);
}

double PhysicsSpace::distance(const ob::State* a, const ob::State* b) const {
  const double* x = a->as<StateType>()->values;
  const double* y = b->as<StateType>()->values;
  double d = std::hypot(x[0] - y[0], x[1] - y[1]);
  if (differential_) d += 0.25 * std::abs(std::remainder(x[3] - y[3], 2 * std::numbers::pi));
  if (product_ == nullptr) return d;
  if (x[values_ + kAutomatonState] != y[values_ + kAutomatonState]) d += kAutomatonStateWeight;
  for (const std::size_t k : product_->named_values) d += std::hypot(x[k] - y[k], x[k + 1] - y[k + 1]);
  return d;
}

ob::StateSamplerPtr PhysicsSpace::allocDefaultStateSampler() const {
  return std::make_shared<RobotPoseSampler>(this, seeds_.next());
}

void PhysicsSpace::registerProjections() {
  if (product_ != nullptr) {
    registerDefaultProjection(std::make_shared<RobotPosition>(this, world_, *product_, values_));
  } else {
    registerDefaultProjection(std::make_shared<RobotPosition>(this, world_, 0, false, values_));
  }
}

const double* physics_values(const ob::State* state, bool compound) {
  const ob::State* low = compound ? state->as<ob::CompoundState>()->components[0] : state;
  return low->as<PhysicsSpace::StateType>()->values;
}

double* physics_values(ob::State* state, bool compound) {
  ob::State* low = compound ? state->as<ob::CompoundState>()->components[0] : state;
  return low->as<PhysicsSpace::StateType>()->values;
}

RobotPosition::RobotPosition(const ob::StateSpace* space, const scenario::World& world, int automaton_states,
                             bool ompl_product, std::size_t values)
    : ob::ProjectionEvaluator(space), automaton_states_(automaton_states), ompl_product_(ompl_product), values_(values) {
  set_grid(world);
}

RobotPosition::RobotPosition(const ob::StateSpace* space, const scenario::World& world, const TaskProduct& product,
                             std::size_t values)
    : ob::ProjectionEvaluator(space),
      automaton_states_(static_cast<int>(product.task.dfa.size())),
      named_values_(product.named_values),
      ompl_product_(false),
      values_(values) {
  set_grid(world);
}

void RobotPosition::set_grid(const scenario::World& world) {
  const Vec2 size = world.workspace.bounds.size();
  std::vector<double> cells{size.x() / 20, size.y() / 20};
  ob::RealVectorBounds bounds(getDimension());
  set_workspace_bounds(bounds, world);
  if (automaton_states_ > 0) cells.push_back(1.0), bounds.setLow(2, -0.5), bounds.setHigh(2, automaton_states_ - 0.5);
  for (size_t i = 0; i < named_values_.size(); ++i) {
    const std::size_t d = 3 + 2 * i;
    cells.push_back(size.x() / 20), cells.push_back(size.y() / 20);
    bounds.setLow(d, world.workspace.bounds.min.x()), bounds.setHigh(d, world.workspace.bounds.max.x());
    bounds.setLow(d + 1, world.workspace.bounds.min.y()), bounds.setHigh(d + 1, world.workspace.bounds.max.y());
  }
  setCellSizes(cells);
  setBounds(bounds);
}

void RobotPosition::project(const ob::State* state, Eigen::Ref<Eigen::VectorXd> out) const {
  const double* v = physics_values(state, ompl_product_);
  out[0] = v[0], out[1] = v[1];
  if (automaton_states_ == 0) return;
  out[2] = ompl_product_ ? state->as<ob::CompoundState>()->as<ob::DiscreteStateSpace::StateType>(2)->value
                         : v[values_ + kAutomatonState];
  for (size_t i = 0; i < named_values_.size(); ++i) {
    out[static_cast<Eigen::Index>(3 + 2 * i)] = v[named_values_[i]];
    out[static_cast<Eigen::Index>(4 + 2 * i)] = v[named_values_[i] + 1];
  }
}

Vec2 setpoint_of(const oc::Control* control, bool differential) {
  const double* u = control->as<oc::RealVectorControlSpace::ControlType>()->values;
  if (differential) return {u[0], u[1]};
  return {u[0] * std::cos(u[1]), u[0] * std::sin(u[1])};
}

void set_control(oc::Control* control, const Vec2& setpoint, bool differential) {
  double* u = control->as<oc::RealVectorControlSpace::ControlType>()->values;
  if (differential) {
    u[0] = setpoint.x(), u[1] = setpoint.y();
  } else {
    u[0] = setpoint.norm(), u[1] = std::atan2(setpoint.y(), setpoint.x());
  }
}

}  // namespace physltl::planners::ompl
