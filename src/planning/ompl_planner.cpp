#include "ompl_planner.h"

#include "checked_simulation.h"
#include "control_sampler.h"
#include "physltl/geometry/free_space.h"
#include "physltl/planning/ompl_automaton.h"

#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/DiscreteStateSpace.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/control/DirectedControlSampler.h>
#include <ompl/control/PathControl.h>
#include <ompl/control/PlannerData.h>
#include <ompl/control/planners/kpiece/KPIECE1.h>
#include <ompl/control/planners/ltl/LTLPlanner.h>
#include <ompl/control/planners/ltl/LTLProblemDefinition.h>
#include <ompl/control/planners/ltl/ProductGraph.h>
#include <ompl/control/planners/ltl/PropositionalDecomposition.h>
#include <ompl/control/planners/pdst/PDST.h>
#include <ompl/control/planners/rrt/RRT.h>
#include <ompl/control/planners/sst/SST.h>
#include <ompl/control/spaces/RealVectorControlSpace.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <map>
#include <numbers>
#include <optional>

namespace physltl::planning {
namespace {

namespace ob = ompl::base;
namespace oc = ompl::control;

constexpr std::size_t kValuesPerBody = physics::PhysicsState::kValuesPerBody;
// After the physics values, two flags about the step that made the state: it passed the validity checker,
// and it took the robot into a triangle OMPL's product graph does not connect to the one it left (see
// step_neighbours in ompl_planner.h).
constexpr std::size_t kFlags = 2;
// A distance between automaton states, in metres of robot motion: nearer states in another automaton
// state never stand in for one in this one (SST's pruning, the nearest neighbours of RRT).
constexpr double kAutomatonStateWeight = 100.0;

// Seeds for a run's samplers, one after the other from the run's seed: OMPL allocates its samplers in a
// fixed order, so the same seed gives the same samplers.
class SeedSequence {
 public:
  explicit SeedSequence(std::uint64_t seed) : state_(seed) {}
  std::uint_fast32_t next() {
    state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;  // Knuth's MMIX LCG
    return static_cast<std::uint_fast32_t>(state_ >> 33) | 1u;
  }

 private:
  std::uint64_t state_;
};

// The full physics state (exact, so a propagation from a stored state is reproducible), with distances and
// sampling on the robot's pose.
class PhysicsSpace : public ob::RealVectorStateSpace {
 public:
  PhysicsSpace(const scenario::World& world, const physics::PhysicsState& start, SeedSequence& seeds)
      : ob::RealVectorStateSpace(static_cast<unsigned>(start.bodies() * kValuesPerBody + kFlags)),
        seeds_(seeds),
        world_(world),
        differential_(world.robot.drive == scenario::Drive::kDifferential),
        values_(start.bodies() * kValuesPerBody) {
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
    for (std::size_t f = 0; f < kFlags; ++f) b.setLow(values_ + f, 0), b.setHigh(values_ + f, 1);
    setBounds(b);
  }

  std::size_t values() const { return values_; }
  const std::vector<double>& start_values() const { return start_; }
  bool differential() const { return differential_; }
  const scenario::World& world() const { return world_; }

  // The robot's pose: position in metres, and a differential robot's heading at a quarter metre a radian.
  double distance(const ob::State* a, const ob::State* b) const override {
    const double* x = a->as<StateType>()->values;
    const double* y = b->as<StateType>()->values;
    const double d = std::hypot(x[0] - y[0], x[1] - y[1]);
    if (!differential_) return d;
    return d + 0.25 * std::abs(std::remainder(x[3] - y[3], 2 * std::numbers::pi));
  }

  ob::StateSamplerPtr allocDefaultStateSampler() const override;
  void registerProjections() override;

 private:
  SeedSequence& seeds_;
  const scenario::World& world_;
  const bool differential_;
  const std::size_t values_;
  std::vector<double> start_ = std::vector<double>(values_);
};

// Samples (what RRT, SST and PDST grow towards) a pose of the robot anywhere in the workspace, the rest as
// at the start; its generator is seeded from the run's seed.
class RobotPoseSampler : public ob::StateSampler {
 public:
  RobotPoseSampler(const PhysicsSpace* space, std::uint_fast32_t seed) : ob::StateSampler(space), space_(space) {
    rng_.setLocalSeed(seed);
  }
  void sampleUniform(ob::State* state) override {
    const auto& w = space_->world();
    const double r = w.robot.radius;
    place(state, {rng_.uniformReal(w.workspace.bounds.min.x() + r, w.workspace.bounds.max.x() - r),
                  rng_.uniformReal(w.workspace.bounds.min.y() + r, w.workspace.bounds.max.y() - r)},
          rng_.uniformReal(-std::numbers::pi, std::numbers::pi));
  }
  void sampleUniformNear(ob::State* state, const ob::State* near, double distance) override {
    const double* v = near->as<PhysicsSpace::StateType>()->values;
    place(state, {v[0] + rng_.uniformReal(-distance, distance), v[1] + rng_.uniformReal(-distance, distance)}, v[3]);
  }
  void sampleGaussian(ob::State* state, const ob::State* mean, double sigma) override {
    const double* v = mean->as<PhysicsSpace::StateType>()->values;
    place(state, {rng_.gaussian(v[0], sigma), rng_.gaussian(v[1], sigma)}, v[3]);
  }

 private:
  void place(ob::State* state, const Vec2& p, double yaw) const {
    double* v = state->as<PhysicsSpace::StateType>()->values;
    std::copy(space_->start_values().begin(), space_->start_values().end(), v);
    v[0] = p.x(), v[1] = p.y();
    if (space_->differential()) v[3] = yaw;
    v[space_->values()] = 1.0;
    v[space_->values() + 1] = 0.0;
  }
  const PhysicsSpace* space_;
};

ob::StateSamplerPtr PhysicsSpace::allocDefaultStateSampler() const {
  return std::make_shared<RobotPoseSampler>(this, seeds_.next());
}

// The workspace's x and y as the first two dimensions of `bounds`.
void set_workspace_bounds(ob::RealVectorBounds& bounds, const scenario::World& world) {
  bounds.setLow(0, world.workspace.bounds.min.x()), bounds.setHigh(0, world.workspace.bounds.max.x());
  bounds.setLow(1, world.workspace.bounds.min.y()), bounds.setHigh(1, world.workspace.bounds.max.y());
}

// The robot's position, in cells of 1/20 of the workspace (OMPL's default share of the extent), within the
// workspace: KPIECE1's and PDST's grid.
class RobotPosition : public ob::ProjectionEvaluator {
 public:
  // `automaton_states`: 0 for the robot's own space, the automaton's states on OMPL's product.
  RobotPosition(const ob::StateSpace* space, const scenario::World& world, int automaton_states)
      : ob::ProjectionEvaluator(space), product_(automaton_states > 0) {
    const Vec2 size = world.workspace.bounds.size();
    std::vector<double> cells{size.x() / 20, size.y() / 20};
    ob::RealVectorBounds bounds(getDimension());
    set_workspace_bounds(bounds, world);
    if (product_) cells.push_back(1.0), bounds.setLow(2, -0.5), bounds.setHigh(2, automaton_states - 0.5);
    setCellSizes(cells);
    setBounds(bounds);
  }
  unsigned int getDimension() const override { return product_ ? 3 : 2; }
  // On OMPL's product the automaton state is a third coordinate, so cells never mix automaton states.
  void project(const ob::State* state, Eigen::Ref<Eigen::VectorXd> out) const override {
    const ob::State* low = product_ ? state->as<ob::CompoundState>()->components[0] : state;
    const double* v = low->as<PhysicsSpace::StateType>()->values;
    out[0] = v[0], out[1] = v[1];
    if (product_) out[2] = state->as<ob::CompoundState>()->as<ob::DiscreteStateSpace::StateType>(2)->value;
  }

 private:
  const bool product_;
};

void PhysicsSpace::registerProjections() {
  registerDefaultProjection(std::make_shared<RobotPosition>(this, world_, 0));
}

// A control is a set-point: a holonomic robot's (speed, heading), a differential robot's (forward speed,
// turn rate). Both ways:
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

// What the propagator did: restores, steps, and steps refused for landing beyond step_neighbours().
struct GuardCounts {
  long long restores = 0;  // propagations started from a state other than the last one reached
  long long steps = 0;
  long long skips = 0;
};

// OMPL's propagator: one ODE step per call (OMPL calls it once per step of its propagation step size),
// checked as our planner checks it. The step's validity and a step beyond step_neighbours() are written into
// the state's flags for the validity checker. OMPL usually continues from the state it was just given, so
// the simulation restores a state only when it is another one.
class PhysicsPropagator : public oc::StatePropagator {
 public:
  PhysicsPropagator(const oc::SpaceInformationPtr& si, const PhysicsSpace& space, const scenario::World& world,
                    const knowledge::AbstractKnowledge& knowledge, const decomposition::Decomposition& decomposition,
                    const std::vector<std::vector<int>>& neighbours, GuardCounts& counts)
      : oc::StatePropagator(si),
        space_(space),
        world_(world),
        decomposition_(decomposition),
        neighbours_(neighbours),
        counts_(counts),
        simulation_(world, knowledge, knowledge::ValidityMode::kKnowledge),
        last_(space.values(), 0.0) {}

  void propagate(const ob::State* from, const oc::Control* control, double duration, ob::State* to) const override {
    const double* in = from->as<PhysicsSpace::StateType>()->values;
    const std::size_t n = space_.values();
    if (!at_last_ || std::memcmp(in, last_.data(), n * sizeof(double)) != 0) {
      simulation_.restore(physics::PhysicsState::from_values({in, n}));
      ++counts_.restores;
    }
    const Vec2 setpoint = setpoint_of(control, space_.differential());
    const int steps = std::max(1, static_cast<int>(std::lround(duration / world_.planner.step_size)));
    bool valid = true;
    bool beyond_graph = false;
    int triangle = decomposition_.locate({in[0], in[1]});
    for (int s = 0; s < steps && valid && !beyond_graph; ++s) {
      valid = simulation_.step(setpoint) == knowledge::Violation::kNone;
      ++counts_.steps;
      const int next = decomposition_.locate(simulation_.environment().robot_position);
      const auto& neighbours = neighbours_[static_cast<std::size_t>(triangle)];
      beyond_graph = next != triangle && std::find(neighbours.begin(), neighbours.end(), next) == neighbours.end();
      triangle = next;
    }
    counts_.skips += beyond_graph ? 1 : 0;
    simulation_.save(saved_);
    double* out = to->as<PhysicsSpace::StateType>()->values;
    saved_.copy_values({out, n});
    out[n] = valid ? 1.0 : 0.0;
    out[n + 1] = beyond_graph ? 1.0 : 0.0;
    std::copy(out, out + n, last_.begin());
    at_last_ = true;
  }

  bool canPropagateBackward() const override { return false; }

 private:
  const PhysicsSpace& space_;
  const scenario::World& world_;
  const decomposition::Decomposition& decomposition_;
  const std::vector<std::vector<int>>& neighbours_;
  GuardCounts& counts_;
  mutable CheckedSimulation simulation_;
  mutable physics::PhysicsState saved_;
  mutable std::vector<double> last_;
  mutable bool at_last_ = false;
};

class StepValidity : public ob::StateValidityChecker {
 public:
  StepValidity(const ob::SpaceInformationPtr& si, std::size_t values) : ob::StateValidityChecker(si), values_(values) {}
  bool isValid(const ob::State* state) const override {
    const double* v = state->as<PhysicsSpace::StateType>()->values;
    return v[values_] == 1.0 && v[values_ + 1] == 0.0;
  }

 private:
  const std::size_t values_;
};

// OMPL's uniform control sampler, with a generator seeded from the run's seed.
class SeededControlSampler : public oc::RealVectorControlUniformSampler {
 public:
  SeededControlSampler(const oc::ControlSpace* space, std::uint_fast32_t seed) : oc::RealVectorControlUniformSampler(space) {
    rng_.setLocalSeed(seed);
  }
};

// Our knowledge-guided control sampler (the knowledge planner's) for OMPL's planners, as an option: it
// reads the world and kappa at the state a control starts from and aims at a target, pushing a body in the
// way from an mRegion along an allowed direction.
class OurSampling {
 public:
  OurSampling(const scenario::World& world, const knowledge::AbstractKnowledge& knowledge, std::uint64_t seed)
      : world_(world), sampler_(world, knowledge, true), simulation_(world, knowledge, knowledge::ValidityMode::kKnowledge),
        random_(seed) {}

  // Samples from `state` (a state of OMPL's product) towards `target`, or towards a point drawn at random in
  // the workspace; writes the set-point into `control` and returns the control's steps.
  unsigned sample(oc::Control* control, const ob::State* state, const std::optional<Vec2>& target) {
    const ob::State* low = state->as<ob::CompoundState>()->components[0];
    const double* v = low->as<PhysicsSpace::StateType>()->values;
    simulation_.restore(physics::PhysicsState::from_values({v, (world_.movable_bodies.size() + 1) * kValuesPerBody}));
    const auto& b = world_.workspace.bounds;
    const Vec2 aim = target ? *target : Vec2(random_.uniform(b.min.x(), b.max.x()), random_.uniform(b.min.y(), b.max.y()));
    const Control c = sampler_.sample(simulation_.environment(), simulation_.kappa(), aim, true, random_);
    set_control(control, c.setpoint, world_.robot.drive == scenario::Drive::kDifferential);
    return static_cast<unsigned>(c.steps);
  }

 private:
  const scenario::World& world_;
  const ControlSampler sampler_;
  CheckedSimulation simulation_;
  Random random_;
};

// For KPIECE1 and LTLPlanner (which sample a control at a state, then its steps) and SST (which samples
// without a state: then uniformly, as OMPL's sampler does).
class OurControlSampler : public oc::ControlSampler {
 public:
  OurControlSampler(const oc::ControlSpace* space, const scenario::World& world,
                    const knowledge::AbstractKnowledge& knowledge, std::uint64_t seed)
      : oc::ControlSampler(space), sampling_(world, knowledge, seed), uniform_(space, static_cast<std::uint_fast32_t>(seed | 1u)) {}
  void sample(oc::Control* control) override { uniform_.sample(control); }
  void sample(oc::Control* control, const ob::State* state) override { steps_ = sampling_.sample(control, state, std::nullopt); }
  void sampleNext(oc::Control* control, const oc::Control*, const ob::State* state) override { sample(control, state); }
  unsigned int sampleStepCount(unsigned int min_steps, unsigned int max_steps) override {
    return steps_ >= min_steps && steps_ <= max_steps ? steps_ : uniform_.sampleStepCount(min_steps, max_steps);
  }

 private:
  OurSampling sampling_;
  SeededControlSampler uniform_;
  unsigned steps_ = 0;
};

// For RRT and PDST, which grow towards a sampled state: our sampler aims at it.
class OurDirectedSampler : public oc::DirectedControlSampler {
 public:
  OurDirectedSampler(const oc::SpaceInformation* si, const scenario::World& world,
                     const knowledge::AbstractKnowledge& knowledge, std::uint64_t seed)
      : oc::DirectedControlSampler(si), sampling_(world, knowledge, seed) {}
  unsigned int sampleTo(oc::Control* control, const ob::State* source, ob::State* dest) override {
    const double* d = dest->as<ob::CompoundState>()->components[0]->as<PhysicsSpace::StateType>()->values;
    const unsigned steps = sampling_.sample(control, source, Vec2(d[0], d[1]));
    return si_->propagateWhileValid(source, control, static_cast<int>(steps), dest);
  }
  unsigned int sampleTo(oc::Control* control, const oc::Control*, const ob::State* source, ob::State* dest) override {
    return sampleTo(control, source, dest);
  }

 private:
  OurSampling sampling_;
};

// Our triangulation as OMPL's decomposition: regions are triangles, located by the robot's position.
class Triangles : public oc::Decomposition {
 public:
  Triangles(const decomposition::Decomposition& decomposition, const scenario::World& world,
            const std::vector<std::vector<int>>& neighbours)
      : oc::Decomposition(2, bounds_of(world)), decomposition_(decomposition), neighbours_(neighbours) {}
  int getNumRegions() const override { return decomposition_.size(); }
  double getRegionVolume(int region) override { return triangle(region).area; }
  int locateRegion(const ob::State* state) const override {
    const double* v = state->as<PhysicsSpace::StateType>()->values;
    return decomposition_.locate({v[0], v[1]});
  }
  void project(const ob::State* state, std::vector<double>& coordinates) const override {
    const double* v = state->as<PhysicsSpace::StateType>()->values;
    coordinates = {v[0], v[1]};
  }
  void getNeighbors(int region, std::vector<int>& neighbours) const override {
    const auto& n = neighbours_[static_cast<std::size_t>(region)];
    neighbours.insert(neighbours.end(), n.begin(), n.end());
  }
  void sampleFromRegion(int region, ompl::RNG& rng, std::vector<double>& coordinates) const override {
    const double u = rng.uniform01(), v = rng.uniform01();
    const Vec2 p = triangle(region).point_at(u, v);
    coordinates = {p.x(), p.y()};
  }
  void sampleFullState(const ob::StateSamplerPtr& sampler, const std::vector<double>& coordinates,
                       ob::State* state) const override {
    sampler->sampleUniform(state);
    double* v = state->as<PhysicsSpace::StateType>()->values;
    v[0] = coordinates[0], v[1] = coordinates[1];
  }

 private:
  static ob::RealVectorBounds bounds_of(const scenario::World& world) {
    ob::RealVectorBounds b(2);
    set_workspace_bounds(b, world);
    return b;
  }
  const decomposition::Triangle& triangle(int region) const {
    return decomposition_.triangles()[static_cast<std::size_t>(region)];
  }
  const decomposition::Decomposition& decomposition_;
  const std::vector<std::vector<int>>& neighbours_;
};

// Each triangle's label: "in region r" for a triangle of region r, "in no region" otherwise, exactly the
// letters the automaton's transitions are keyed by (to_ompl_automaton).
class RegionLabels : public oc::PropositionalDecomposition {
 public:
  RegionLabels(const oc::DecompositionPtr& triangles, const decomposition::Decomposition& decomposition, int regions)
      : oc::PropositionalDecomposition(triangles), decomposition_(decomposition), regions_(regions) {}
  oc::World worldAtRegion(int triangle) override {
    return region_letter(regions_, decomposition_.triangles()[static_cast<std::size_t>(triangle)].region);
  }
  int getNumProps() const override { return regions_; }

 private:
  const decomposition::Decomposition& decomposition_;
  const int regions_;
};

// Reached when the co-safe automaton accepts. OMPL's own goal for the product has no distance (every
// state reads as infinitely far, which leaves KPIECE1 nothing to prefer); this one gives the automaton's
// distance to acceptance.
class TaskGoal : public ob::Goal {
 public:
  TaskGoal(const oc::LTLSpaceInformationPtr& si, const oc::AutomatonPtr& automaton)
      : ob::Goal(si), ltl_(si), automaton_(automaton) {}
  bool isSatisfied(const ob::State* state) const override { return isSatisfied(state, nullptr); }
  bool isSatisfied(const ob::State* state, double* distance) const override {
    const int q = ltl_->getProdGraphState(state)->getCosafeState();
    const bool satisfied = q >= 0 && automaton_->isAccepting(static_cast<unsigned>(q));
    if (distance != nullptr) {
      *distance = q < 0 ? std::numeric_limits<double>::max() : automaton_->distFromAccepting(static_cast<unsigned>(q));
    }
    return satisfied;
  }

 private:
  oc::LTLSpaceInformationPtr ltl_;
  oc::AutomatonPtr automaton_;
};

// OMPL's planners with their generator seeded from the run's (RNG::setLocalSeed: OMPL's process-wide
// RNG::setSeed takes effect only before the first generator exists).
template <class Planner>
class Seeded : public Planner {
 public:
  template <class... Args>
  explicit Seeded(std::uint_fast32_t seed, Args&&... args) : Planner(std::forward<Args>(args)...) {
    this->rng_.setLocalSeed(seed);
  }
};

// OMPL 1.5's SST deletes its witnesses without freeing their states and controls (SST::freeMemory; still
// so in OMPL's master), which leaks a state and a control per witness every run: free them first.
class SeededSst : public Seeded<oc::SST> {
 public:
  using Seeded<oc::SST>::Seeded;
  ~SeededSst() override {
    if (!witnesses_) return;
    std::vector<Motion*> witnesses;
    witnesses_->list(witnesses);
    for (Motion* w : witnesses) {
      if (w->state_ != nullptr) si_->freeState(w->state_);
      if (w->control_ != nullptr) siC_->freeControl(w->control_);
      w->state_ = nullptr;
      w->control_ = nullptr;
    }
  }
};

// LTLPlanner explores each lead for this long, in wall-clock time: OMPL's default.
constexpr double kLtlExploreTime = 0.5;  // s

ob::PlannerPtr make_planner(OmplAlgorithm kind, const oc::LTLSpaceInformationPtr& si, const oc::ProductGraphPtr& product,
                            const scenario::World& world, int automaton_states, std::uint_fast32_t seed) {
  switch (kind) {
    case OmplAlgorithm::kLtl:
      return std::make_shared<Seeded<oc::LTLPlanner>>(seed, si, product, kLtlExploreTime);
    case OmplAlgorithm::kRrt:
      return std::make_shared<Seeded<oc::RRT>>(seed, si);
    case OmplAlgorithm::kKpiece: {
      auto planner = std::make_shared<Seeded<oc::KPIECE1>>(seed, si);
      planner->setProjectionEvaluator(std::make_shared<RobotPosition>(si->getStateSpace().get(), world, automaton_states));
      return planner;
    }
    case OmplAlgorithm::kSst:
      return std::make_shared<SeededSst>(seed, si);
    case OmplAlgorithm::kPdst: {
      auto planner = std::make_shared<Seeded<oc::PDST>>(seed, si);
      planner->setProjectionEvaluator(std::make_shared<RobotPosition>(si->getStateSpace().get(), world, automaton_states));
      return planner;
    }
  }
  throw std::invalid_argument("not an OMPL planner");
}

}  // namespace

std::vector<std::vector<int>> step_neighbours(const decomposition::Decomposition& decomposition, double reach) {
  const auto& triangles = decomposition.triangles();
  std::vector<geometry::Polygon> shapes;
  std::vector<geometry::Rect> bounds;
  for (const auto& t : triangles) {
    shapes.push_back(geometry::Polygon{{t.corners.begin(), t.corners.end()}});
    bounds.push_back(shapes.back().bounds());
  }
  std::vector<std::vector<int>> neighbours(triangles.size());
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    neighbours[i] = triangles[i].neighbors;
    for (std::size_t j = 0; j < triangles.size(); ++j) {
      const auto& a = bounds[i];
      const auto& b = bounds[j];
      if (i == j || b.min.x() > a.max.x() + reach || b.max.x() < a.min.x() - reach || b.min.y() > a.max.y() + reach ||
          b.max.y() < a.min.y() - reach) {
        continue;
      }
      Vec2 p, q;
      if (geometry::distance(shapes[i], shapes[j], p, q) <= reach &&
          std::find(neighbours[i].begin(), neighbours[i].end(), static_cast<int>(j)) == neighbours[i].end()) {
        neighbours[i].push_back(static_cast<int>(j));
      }
    }
  }
  return neighbours;
}

PlanResult plan_with_ompl(const Problem& problem, const PlannerOptions& options, OmplAlgorithm algorithm) {
  const scenario::World& world = problem.world;
  const TaskAutomaton& task = problem.task;
  const knowledge::AbstractKnowledge& knowledge = problem.knowledge;
  const decomposition::Decomposition& decomposition = problem.decomposition;
  if (task.names_bodies() || task.ends_at_rest()) {
    throw std::invalid_argument("OMPL's product takes co-safe tasks about the robot's regions only (registry.h)");
  }
  const auto started = std::chrono::steady_clock::now();
  // Every generator OMPL makes without a seed of its own takes the next from its process-wide sequence
  // (OMPL complains once it has started); ours are seeded below.
  ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
  SeedSequence seeds(options.seed);
  ompl::RNG::setSeed(seeds.next());
  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);

  const physics::PhysicsState start = physics::Simulation(world).save();
  auto space = std::make_shared<PhysicsSpace>(world, start, seeds);
  auto controls = std::make_shared<oc::RealVectorControlSpace>(space, 2);
  ob::RealVectorBounds control_bounds(2);
  const bool differential = world.robot.drive == scenario::Drive::kDifferential;
  if (differential) {
    control_bounds.setLow(0, -world.robot.max_speed), control_bounds.setHigh(0, world.robot.max_speed);
    control_bounds.setLow(1, -world.robot.max_turn_rate), control_bounds.setHigh(1, world.robot.max_turn_rate);
  } else {
    control_bounds.setLow(0, 0.0), control_bounds.setHigh(0, world.robot.max_speed);
    control_bounds.setLow(1, -std::numbers::pi), control_bounds.setHigh(1, std::numbers::pi);
  }
  controls->setBounds(control_bounds);
  if (options.ompl_control_sampler == OmplControlSampler::kOurs) {
    controls->setControlSamplerAllocator([&](const oc::ControlSpace* cs) {
      return std::make_shared<OurControlSampler>(cs, world, knowledge, seeds.next());
    });
  } else {
    controls->setControlSamplerAllocator([&seeds](const oc::ControlSpace* cs) {
      return std::make_shared<SeededControlSampler>(cs, seeds.next());
    });
  }

  auto low = std::make_shared<oc::SpaceInformation>(space, controls);
  GuardCounts counts;
  // The fastest a valid step goes: the robot within its limit's tolerance (knowledge::kLimitTolerance).
  const double reach = 1.02 * world.robot.max_speed * world.planner.step_size;
  const std::vector<std::vector<int>> neighbours = step_neighbours(decomposition, reach);
  low->setStatePropagator(
      std::make_shared<PhysicsPropagator>(low, *space, world, knowledge, decomposition, neighbours, counts));
  low->setStateValidityChecker(std::make_shared<StepValidity>(low, space->values()));
  low->setPropagationStepSize(world.planner.step_size);
  low->setMinMaxControlDuration(static_cast<unsigned>(world.planner.min_steps), static_cast<unsigned>(world.planner.max_steps));

  auto automaton = to_ompl_automaton(task);
  const int regions = static_cast<int>(world.regions.size());
  auto labels = std::make_shared<RegionLabels>(std::make_shared<Triangles>(decomposition, world, neighbours), decomposition, regions);
  auto product = std::make_shared<oc::ProductGraph>(labels, automaton);
  auto si = std::make_shared<oc::LTLSpaceInformation>(low, product);
  si->getStateSpace()->as<ob::CompoundStateSpace>()->setSubspaceWeight(2, kAutomatonStateWeight);
  if (options.ompl_control_sampler == OmplControlSampler::kOurs) {
    si->setDirectedControlSamplerAllocator([&](const oc::SpaceInformation* s) {
      return std::make_shared<OurDirectedSampler>(s, world, knowledge, seeds.next());
    });
  }
  si->setup();

  auto definition = std::make_shared<oc::LTLProblemDefinition>(si);
  definition->setGoal(std::make_shared<TaskGoal>(si, automaton));
  // The start with its own label read (OMPL's addLowerStartState leaves it unread).
  ob::State* full = si->allocState();
  ob::State* low_start = low->allocState();
  double* v = low_start->as<PhysicsSpace::StateType>()->values;
  start.copy_values({v, space->values()});
  v[space->values()] = 1.0, v[space->values() + 1] = 0.0;
  si->getFullState(low_start, full);
  const int start_triangle = decomposition.locate(world.robot.start);
  const int start_q = automaton->step(automaton->getStartState(), labels->worldAtRegion(start_triangle));
  full->as<ob::CompoundState>()->as<ob::DiscreteStateSpace::StateType>(2)->value = start_q;
  definition->addStartState(full);
  si->freeState(full);
  low->freeState(low_start);
  if (algorithm == OmplAlgorithm::kSst) {
    // SST keeps improving its solution until the cost threshold: stop at the first.
    auto objective = std::make_shared<ob::PathLengthOptimizationObjective>(si);
    objective->setCostThreshold(objective->infiniteCost());
    definition->setOptimizationObjective(objective);
  }

  const ob::PlannerPtr planner = make_planner(algorithm, si, product, world, static_cast<int>(task.dfa.size()), seeds.next());
  planner->setProblemDefinition(definition);
  planner->setup();

  const ob::PlannerTerminationCondition ptc = ob::plannerOrTerminationCondition(
      ob::timedPlannerTerminationCondition(options.time_limit),
      ob::PlannerTerminationCondition([&] { return options.stop != nullptr && options.stop->load(std::memory_order_relaxed); }));
  const ob::PlannerStatus status = planner->solve(ptc);

  PlanResult result;
  result.solved = definition->hasExactSolution();
  result.stop_reason = result.solved                                                   ? "solved"
                       : options.stop != nullptr && options.stop->load()               ? "interrupted"
                       : status == ob::PlannerStatus::TIMEOUT || status == ob::PlannerStatus::APPROXIMATE_SOLUTION
                           ? "time limit"
                           : "no solution";
  if (result.solved) {
    const auto path = std::static_pointer_cast<oc::PathControl>(definition->getLowerSolutionPath());
    for (std::size_t i = 0; i < path->getControlCount(); ++i) {
      const int steps = static_cast<int>(std::lround(path->getControlDuration(i) / world.planner.step_size));
      result.plan.controls.push_back({setpoint_of(path->getControl(i), differential), steps});
      const double* values = path->getState(i + 1)->as<PhysicsSpace::StateType>()->values;
      result.plan.states.push_back(physics::PhysicsState::from_values({values, space->values()}));
    }
  }
  // The tree, for tree.png: OMPL's control planners give their planner data; LTLPlanner only its states.
  oc::PlannerData data(si);
  planner->getPlannerData(data);
  const auto robot = [&](const ob::State* s) {
    const double* x = si->getLowLevelState(s)->as<PhysicsSpace::StateType>()->values;
    return Vec2(x[0], x[1]);
  };
  for (unsigned i = 0; i < data.numVertices(); ++i) {
    std::vector<unsigned> out;
    data.getEdges(i, out);
    for (unsigned j : out) {
      const ob::State* to = data.getVertex(j).getState();
      result.tree.push_back({robot(data.getVertex(i).getState()), robot(to),
                             si->getProdGraphState(to)->getCosafeState()});
    }
  }
  result.stats.tree_nodes = data.numVertices();
  if (algorithm == OmplAlgorithm::kLtl) {
    std::vector<ob::State*> states;
    std::static_pointer_cast<oc::LTLPlanner>(planner)->getTree(states);
    result.stats.tree_nodes = static_cast<long long>(states.size());
  }
  result.stats.propagations = counts.restores;
  result.stats.physics_steps = counts.steps;
  result.stats.cell_skips_refused = counts.skips;
  result.stats.planning_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  std::map<std::string, std::string> params;
  planner->params().getParams(params);
  result.settings = {{"planner", planner->getName()},
                     {"seed", std::to_string(options.seed)},
                     {"propagation_step_size", fmt::format("{}", world.planner.step_size)},
                     {"min_control_duration", std::to_string(world.planner.min_steps)},
                     {"max_control_duration", std::to_string(world.planner.max_steps)},
                     {"controls", differential ? "(forward speed, turn rate), uniform" : "(speed, heading), uniform"},
                     {"control_sampler", options.ompl_control_sampler == OmplControlSampler::kOurs
                                             ? "ours: the knowledge planner's, towards the target (RRT, PDST) or a random point"
                                             : "OMPL RealVectorControlUniformSampler"},
                     {"state_sampler", "robot pose uniform in the workspace, the rest as at the start"},
                     {"distance", differential ? "robot position + 0.25 m/rad heading" : "robot position"},
                     {"automaton_state_weight", fmt::format("{}", kAutomatonStateWeight)},
                     {"validity", "knowledge (kappa re-inferred every step), cell skips refused"}};
  if (algorithm == OmplAlgorithm::kKpiece || algorithm == OmplAlgorithm::kPdst) {
    result.settings.push_back({"projection", "robot position (cells of 1/20 of the workspace) and automaton state"});
  }
  if (algorithm == OmplAlgorithm::kLtl) result.settings.push_back({"explore_time", fmt::format("{}", kLtlExploreTime)});
  if (algorithm == OmplAlgorithm::kSst) result.settings.push_back({"cost_threshold", "infinite (stop at the first solution)"});
  for (const auto& [name, value] : params) result.settings.push_back({name, value});
  return result;
}

}  // namespace physltl::planning
