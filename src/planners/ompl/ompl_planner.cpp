#include "ompl_planner.h"

#include "control_samplers.h"
#include "decomposition.h"
#include "goals.h"
#include "planners.h"
#include "propagator.h"

#include "ompl_automaton.h"

#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/DiscreteStateSpace.h>
#include <ompl/control/PathControl.h>
#include <ompl/control/PlannerData.h>
#include <ompl/control/planners/ltl/LTLPlanner.h>
#include <ompl/control/planners/ltl/LTLProblemDefinition.h>
#include <ompl/control/planners/ltl/LTLSpaceInformation.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <fmt/format.h>

#include <chrono>
#include <limits>
#include <optional>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>

namespace physltl::planners::ompl {

using geometry::Vec2;

const planning::PlannerParameter& ompl_sampler_parameter() {
  static const planning::PlannerParameter parameter{
      "ompl-sampler",
      "Control sampler of OMPL's planners: ompl (OMPL's uniform one) or ours (the knowledge planner's)",
      {"ompl", "ours"},
      [](const std::string& value) { return value == "ours" ? "OMPL's planners sample controls with ours (--ompl-sampler ours)" : ""; }};
  return parameter;
}

const planning::PlannerParameter& sst_until_parameter() {
  static const planning::PlannerParameter parameter{
      "sst-until",
      "When OMPL's SST stops: limit (keeps lowering its path's length until the time limit) or first (at its first "
      "solution)",
      {"limit", "first"},
      [](const std::string& value) { return value == "first" ? "SST stops at its first solution (--sst-until first)" : ""; }};
  return parameter;
}

namespace {

bool with_our_sampler(const planning::PlannerOptions& options) { return options.parameter(ompl_sampler_parameter()) == "ours"; }
bool sst_improves(const planning::PlannerOptions& options) { return options.parameter(sst_until_parameter()) == "limit"; }

// The set-point space and its sampler: OMPL's uniform one, or ours (options.ompl_control_sampler).
std::shared_ptr<oc::RealVectorControlSpace> make_controls(const std::shared_ptr<PhysicsSpace>& space,
                                                          const knowledge::AbstractKnowledge& knowledge,
                                                          const planning::PlannerOptions& options, SeedSequence& seeds,
                                                          bool ompl_product) {
  const scenario::World& world = space->world();
  auto controls = std::make_shared<oc::RealVectorControlSpace>(space, 2);
  ob::RealVectorBounds control_bounds(2);
  if (space->differential()) {
    control_bounds.setLow(0, -world.robot.max_speed), control_bounds.setHigh(0, world.robot.max_speed);
    control_bounds.setLow(1, -world.robot.max_turn_rate), control_bounds.setHigh(1, world.robot.max_turn_rate);
  } else {
    control_bounds.setLow(0, 0.0), control_bounds.setHigh(0, world.robot.max_speed);
    control_bounds.setLow(1, -std::numbers::pi), control_bounds.setHigh(1, std::numbers::pi);
  }
  controls->setBounds(control_bounds);
  if (with_our_sampler(options)) {
    controls->setControlSamplerAllocator([&world, &knowledge, &seeds, ompl_product](const oc::ControlSpace* cs) {
      return std::make_shared<OurControlSampler>(cs, world, knowledge, seeds.next(), ompl_product);
    });
  } else {
    controls->setControlSamplerAllocator([&seeds](const oc::ControlSpace* cs) {
      return std::make_shared<SeededControlSampler>(cs, seeds.next());
    });
  }
  return controls;
}

// The physics space's information: the propagator, the validity checker and the control durations.
oc::SpaceInformationPtr physics_information(const std::shared_ptr<PhysicsSpace>& space,
                                            const std::shared_ptr<oc::RealVectorControlSpace>& controls,
                                            const planning::Problem& problem, const std::vector<std::vector<int>>& neighbours,
                                            GuardCounts& counts) {
  const scenario::World& world = problem.world;
  auto si = std::make_shared<oc::SpaceInformation>(space, controls);
  si->setStatePropagator(
      std::make_shared<PhysicsPropagator>(si, *space, problem.knowledge, problem.decomposition, neighbours, counts));
  si->setStateValidityChecker(std::make_shared<StepValidity>(si, space->values()));
  si->setPropagationStepSize(world.planner.step_size);
  si->setMinMaxControlDuration(static_cast<unsigned>(world.planner.min_steps), static_cast<unsigned>(world.planner.max_steps));
  return si;
}

// The start: the World's initial physics state, valid, with its automaton state on our product.
void write_start(double* v, const physics::PhysicsState& start, const PhysicsSpace& space, int automaton_state) {
  start.copy_values({v, space.values()});
  v[space.values() + kValid] = 1.0, v[space.values() + kBeyondGraph] = 0.0;
  if (space.product() != nullptr) v[space.values() + kAutomatonState] = automaton_state;
}

// What a search on either product needs to be run and read.
struct Search {
  oc::SpaceInformationPtr si;  // the one the planner searches
  ob::ProblemDefinitionPtr definition;
  ob::ProjectionEvaluatorPtr projection;
  oc::ProductGraphPtr product;  // OMPL's; null on ours
  std::function<Vec2(const ob::State*)> robot;
  std::function<int(const ob::State*)> automaton_state;
};

Search on_ompls_product(const planning::Problem& problem, const std::shared_ptr<PhysicsSpace>& space,
                        const oc::SpaceInformationPtr& low, const std::vector<std::vector<int>>& neighbours,
                        const planning::PlannerOptions& options, SeedSequence& seeds, const physics::PhysicsState& start) {
  const scenario::World& world = problem.world;
  auto automaton = to_ompl_automaton(problem.task);
  auto labels = std::make_shared<RegionLabels>(std::make_shared<Triangles>(problem.decomposition, world, neighbours),
                                               problem.decomposition, static_cast<int>(world.regions.size()));
  auto product = std::make_shared<oc::ProductGraph>(labels, automaton);
  auto si = std::make_shared<oc::LTLSpaceInformation>(low, product);
  si->getStateSpace()->as<ob::CompoundStateSpace>()->setSubspaceWeight(2, kAutomatonStateWeight);
  if (with_our_sampler(options)) {
    si->setDirectedControlSamplerAllocator([&world, &problem, &seeds](const oc::SpaceInformation* s) {
      return std::make_shared<OurDirectedSampler>(s, world, problem.knowledge, seeds.next(), true);
    });
  }
  si->setup();

  auto definition = std::make_shared<oc::LTLProblemDefinition>(si);
  definition->setGoal(std::make_shared<TaskGoal>(si, automaton));
  // The start with its own label read (OMPL's addLowerStartState leaves it unread).
  ob::State* full = si->allocState();
  ob::State* low_start = low->allocState();
  write_start(low_start->as<PhysicsSpace::StateType>()->values, start, *space, 0);
  si->getFullState(low_start, full);
  const int start_triangle = problem.decomposition.locate(world.robot.start);
  const int start_q = automaton->step(automaton->getStartState(), labels->worldAtRegion(start_triangle));
  full->as<ob::CompoundState>()->as<ob::DiscreteStateSpace::StateType>(2)->value = start_q;
  definition->addStartState(full);
  si->freeState(full);
  low->freeState(low_start);
  auto projection = std::make_shared<RobotPosition>(si->getStateSpace().get(), world,
                                                    static_cast<int>(problem.task.dfa.size()), true, space->values());
  const auto robot = [si](const ob::State* s) {
    const double* x = si->getLowLevelState(s)->as<PhysicsSpace::StateType>()->values;
    return Vec2(x[0], x[1]);
  };
  const auto automaton_state = [si](const ob::State* s) { return si->getProdGraphState(s)->getCosafeState(); };
  return {si, definition, projection, product, robot, automaton_state};
}

Search on_our_product(const planning::Problem& problem, const std::shared_ptr<PhysicsSpace>& space, const oc::SpaceInformationPtr& si,
                      const planning::PlannerOptions& options, SeedSequence& seeds, const physics::PhysicsState& start) {
  const scenario::World& world = problem.world;
  if (with_our_sampler(options)) {
    si->setDirectedControlSamplerAllocator([&world, &problem, &seeds](const oc::SpaceInformation* s) {
      return std::make_shared<OurDirectedSampler>(s, world, problem.knowledge, seeds.next(), false);
    });
  }
  si->setup();
  auto definition = std::make_shared<ob::ProblemDefinition>(si);
  definition->setGoal(std::make_shared<ProductGoal>(si, *space, problem.knowledge));
  ob::State* first = si->allocState();
  write_start(first->as<PhysicsSpace::StateType>()->values, start, *space,
              problem.task.start_state(scenario::EnvironmentState::initial(world)));
  definition->addStartState(first);
  si->freeState(first);
  auto projection = std::make_shared<RobotPosition>(space.get(), world, *space->product(), space->values());
  const std::size_t n = space->values();
  const auto robot = [](const ob::State* s) {
    const double* x = s->as<PhysicsSpace::StateType>()->values;
    return Vec2(x[0], x[1]);
  };
  const auto automaton_state = [n](const ob::State* s) {
    return static_cast<int>(s->as<PhysicsSpace::StateType>()->values[n + kAutomatonState]);
  };
  return {si, definition, projection, nullptr, robot, automaton_state};
}

// The solution's controls and the states after them; on our product, braking to rest appended where the
// task ends at rest.
planning::Plan solution_plan(const Search& search, const PhysicsSpace& space) {
  planning::Plan plan;
  const bool ompl_product = search.product != nullptr;
  const auto path = std::static_pointer_cast<oc::PathControl>(
      ompl_product ? std::static_pointer_cast<oc::LTLProblemDefinition>(search.definition)->getLowerSolutionPath()
                   : search.definition->getSolutionPath());
  for (std::size_t i = 0; i < path->getControlCount(); ++i) {
    const int steps = static_cast<int>(std::lround(path->getControlDuration(i) / space.world().planner.step_size));
    plan.controls.push_back({setpoint_of(path->getControl(i), space.differential()), steps});
    const double* values = path->getState(i + 1)->as<PhysicsSpace::StateType>()->values;
    plan.states.push_back(physics::PhysicsState::from_values({values, space.values()}));
  }
  if (!ompl_product) {
    const auto& goal = *search.definition->getGoal()->as<ProductGoal>();
    const planning::Plan brake = *goal.braking(path->getStates().back());
    plan.controls.insert(plan.controls.end(), brake.controls.begin(), brake.controls.end());
    plan.states.insert(plan.states.end(), brake.states.begin(), brake.states.end());
  }
  return plan;
}

// An improving SST solved in slices of kSstProgressSlice, its best plan's motion time read between them
// (OMPL 1.5's control SST reports no intermediate solutions): `progress` gets (seconds after its first plan,
// motion seconds) for each better one.
ob::PlannerStatus solve_in_slices(ob::Planner& planner, const ob::PlannerTerminationCondition& ptc, const Search& search,
                                  const PhysicsSpace& space, std::vector<std::pair<double, double>>& progress) {
  constexpr double kSstProgressSlice = 0.25;  // s
  const auto started = std::chrono::steady_clock::now();
  std::optional<double> first_found;
  double best = std::numeric_limits<double>::infinity();
  ob::PlannerStatus status;
  std::size_t solutions = 0;
  do {
    status = planner.solve(ob::plannerOrTerminationCondition(ptc, ob::timedPlannerTerminationCondition(kSstProgressSlice)));
    // A plan is made (braking included) only when the slice added a solution.
    if (!search.definition->hasExactSolution() || search.definition->getSolutionCount() == solutions) continue;
    solutions = search.definition->getSolutionCount();
    const double now = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    const double motion = static_cast<double>(solution_plan(search, space).total_steps()) * space.world().planner.step_size;
    if (!first_found) first_found = now;
    if (motion < best) best = motion, progress.push_back({now - *first_found, motion});
  } while (!ptc());
  return status;
}

std::vector<std::pair<std::string, std::string>> settings_of(const ob::Planner& planner, OmplAlgorithm algorithm,
                                                             const scenario::World& world, const planning::PlannerOptions& options,
                                                             bool ompl_product) {
  const bool differential = world.robot.drive == scenario::Drive::kDifferential;
  std::vector<std::pair<std::string, std::string>> settings = {
      {"planner", planner.getName()},
      {"seed", std::to_string(options.seed)},
      {"propagation_step_size", fmt::format("{}", world.planner.step_size)},
      {"min_control_duration", std::to_string(world.planner.min_steps)},
      {"max_control_duration", std::to_string(world.planner.max_steps)},
      {"controls", differential ? "(forward speed, turn rate), uniform" : "(speed, heading), uniform"},
      {"control_sampler", with_our_sampler(options)
                              ? "ours: the knowledge planner's, towards the target (RRT, PDST) or a random point"
                              : "OMPL RealVectorControlUniformSampler"},
      {"state_sampler", "robot pose uniform in the workspace, the rest as at the start"},
      {"distance", differential ? "robot position + 0.25 m/rad heading" : "robot position"},
      {"automaton_state_weight", fmt::format("{}", kAutomatonStateWeight)},
      {"validity", "knowledge (kappa re-inferred every step), cell skips refused"}};
  if (!ompl_product) {
    settings.push_back({"product", "ours: the automaton state in the physics state, stepped on every step's full letter"});
  }
  if (algorithm == OmplAlgorithm::kKpiece || algorithm == OmplAlgorithm::kPdst) {
    settings.push_back({"projection", "robot position (cells of 1/20 of the workspace) and automaton state"});
  }
  if (algorithm == OmplAlgorithm::kLtl) settings.push_back({"explore_time", fmt::format("{}", kLtlExploreTime)});
  if (algorithm == OmplAlgorithm::kSst) {
    settings.push_back({"cost_threshold", sst_improves(options) ? "0 (improve until the time limit)" : "infinite (stop at the first solution)"});
  }
  std::map<std::string, std::string> params;
  planner.params().getParams(params);
  for (const auto& [name, value] : params) settings.push_back({name, value});
  return settings;
}

}  // namespace

bool on_our_product(const planning::TaskAutomaton& task) { return task.names_bodies() || task.ends_at_rest(); }

planning::PlanResult plan_with_ompl(const planning::Problem& problem, const planning::PlannerOptions& options, OmplAlgorithm algorithm) {
  const scenario::World& world = problem.world;
  const planning::TaskAutomaton& task = problem.task;
  const bool ours = on_our_product(task);
  if (ours && algorithm == OmplAlgorithm::kLtl) {
    throw std::invalid_argument("LTLPlanner searches OMPL's product, which takes co-safe tasks about the robot's regions only");
  }
  const auto started = std::chrono::steady_clock::now();
  // Every generator OMPL makes without a seed of its own takes the next from its process-wide sequence
  // (OMPL complains once it has started); ours are seeded below.
  ::ompl::msg::setLogLevel(::ompl::msg::LOG_NONE);
  SeedSequence seeds(options.seed);
  ::ompl::RNG::setSeed(seeds.next());
  ::ompl::msg::setLogLevel(::ompl::msg::LOG_WARN);

  const physics::PhysicsState start = physics::Simulation(world).save();
  const std::optional<TaskProduct> product = ours ? std::optional<TaskProduct>(task) : std::nullopt;
  auto space = std::make_shared<PhysicsSpace>(world, start, seeds, product ? &*product : nullptr);
  auto controls = make_controls(space, problem.knowledge, options, seeds, !ours);
  GuardCounts counts;
  // The fastest a valid step goes: the robot within its limit's tolerance (knowledge::kLimitTolerance).
  const double reach = 1.02 * world.robot.max_speed * world.planner.step_size;
  const std::vector<std::vector<int>> neighbours = step_neighbours(problem.decomposition, reach);
  const oc::SpaceInformationPtr low = physics_information(space, controls, problem, neighbours, counts);
  const Search search = ours ? on_our_product(problem, space, low, options, seeds, start)
                             : on_ompls_product(problem, space, low, neighbours, options, seeds, start);
  const bool improving = algorithm == OmplAlgorithm::kSst && sst_improves(options);
  if (algorithm == OmplAlgorithm::kSst) {
    // SST keeps improving its solution until the cost threshold: none it can reach (until the time
    // limit), or any (stop at the first).
    auto objective = std::make_shared<ob::PathLengthOptimizationObjective>(search.si);
    objective->setCostThreshold(improving ? ob::Cost(0.0) : objective->infiniteCost());
    search.definition->setOptimizationObjective(objective);
  }
  planning::PlanResult result;
  const ob::PlannerPtr planner = make_planner(algorithm, search.si, search.product, search.projection, seeds.next());
  planner->setProblemDefinition(search.definition);
  planner->setup();

  // An improving SST would use the whole time limit: it stops at kSstShareOfTimeLimit of it, so that the
  // replay that validates its plan fits in the run's deadline too.
  const base::Deadline until = improving ? options.deadline.sooner(kSstShareOfTimeLimit * options.deadline.seconds_left()) : options.deadline;
  const ob::PlannerTerminationCondition ptc([&] { return until.reached(); });
  const ob::PlannerStatus status = improving ? solve_in_slices(*planner, ptc, search, *space, result.motion_progress) : planner->solve(ptc);

  result.solved = search.definition->hasExactSolution();
  result.stop_reason = result.solved                                                   ? planning::StopReason::kSolved
                       : options.deadline.interrupted()                                ? planning::StopReason::kInterrupted
                       : status == ob::PlannerStatus::TIMEOUT || status == ob::PlannerStatus::APPROXIMATE_SOLUTION
                           ? planning::StopReason::kTimeLimit
                           : planning::StopReason::kNoSolution;
  if (result.solved) result.plan = solution_plan(search, *space);
  result.improved_itself = improving;
  // The tree, for tree.png: OMPL's control planners give their planner data; LTLPlanner only its states.
  oc::PlannerData data(search.si);
  planner->getPlannerData(data);
  for (unsigned i = 0; i < data.numVertices(); ++i) {
    std::vector<unsigned> out;
    data.getEdges(i, out);
    for (unsigned j : out) {
      const ob::State* to = data.getVertex(j).getState();
      result.tree.push_back({search.robot(data.getVertex(i).getState()), search.robot(to), search.automaton_state(to)});
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
  result.stats.own_counts["cell_skips_refused"] = counts.skips;
  result.stats.refused = counts.refused;
  result.stats.planning_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  result.settings = settings_of(*planner, algorithm, world, options, !ours);
  return result;
}

}  // namespace physltl::planners::ompl
