#include "tree_grower.h"

#include "physltl/knowledge/kappa.h"
#include "random.h"

namespace physltl::planning {

TreeGrower::TreeGrower(const scenario::World& world, const TaskAutomaton& task,
                       const knowledge::AbstractKnowledge& knowledge, const decomposition::Decomposition& decomposition,
                       const ProductGraph& graph, bool use_knowledge)
    : task_(task),
      knowledge_(knowledge),
      decomposition_(decomposition),
      graph_(graph),
      mode_(use_knowledge ? knowledge::ValidityMode::kKnowledge : knowledge::ValidityMode::kBaseline),
      sampler_(world, knowledge, use_knowledge),
      regions_(world),
      simulation_(world) {}

void TreeGrower::grow(const Motion& from, const Vec2& target, std::uint64_t seed, Growth& growth) {
  growth = Growth{};
  Random random(seed);
  simulation_.restore(from.state);
  simulation_.read_environment(environment_);
  update_kappa();
  propagate(sampler_.sample(environment_, kappa_, target, random), from.automaton_state, growth);
}

void TreeGrower::propagate(const Control& control, int automaton_state, Growth& growth) {
  int valid_steps = 0;
  bool accepted = false;
  for (int step = 1; step <= control.steps; ++step) {
    simulation_.step(control.setpoint, contacts_);
    ++growth.physics_steps;
    simulation_.read_environment(environment_);
    // VALIDITYCHECKER(E_new, kappa_j), then kappa_{j+1} = INFERENCE(E_new, kappa_j).
    if (!knowledge::is_valid(knowledge_, kappa_, environment_, contacts_, mode_)) {
      growth.stopped_by_invalid_step = true;
      break;
    }
    if (mode_ == knowledge::ValidityMode::kKnowledge) update_kappa();
    const int next = task_.step(automaton_state, regions_.at(environment_.robot_position));
    if (graph_.dead(next)) break;
    automaton_state = next;
    valid_steps = step;
    simulation_.save(last_valid_);
    if (task_.dfa.accepting[automaton_state]) {
      accepted = true;
      break;
    }
  }
  if (valid_steps == 0) return;

  Motion& motion = growth.motion.emplace();
  motion.state = last_valid_;
  motion.robot = Vec2(last_valid_.values[0], last_valid_.values[1]);  // the robot's x, y come first
  motion.control = {control.setpoint, valid_steps};
  motion.automaton_state = automaton_state;
  motion.product_state = graph_.id(decomposition_.locate(motion.robot), automaton_state);
  growth.accepted = accepted;
}

void TreeGrower::update_kappa() {
  if (kappa_valid_) {
    knowledge::reinfer(knowledge_, environment_, kappa_poses_, kappa_);
  } else {
    knowledge::infer(knowledge_, environment_, kappa_);
    kappa_valid_ = true;
  }
  kappa_poses_ = environment_.movable_poses;
}

}  // namespace physltl::planning
