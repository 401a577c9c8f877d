#include "physltl/planning/planner.h"

#include "control_sampler.h"
#include "physltl/knowledge/kappa.h"
#include "physltl/physics/simulation.h"
#include "product_graph.h"
#include "random.h"

#include <algorithm>
#include <chrono>

namespace physltl::planning {
namespace {

constexpr int kExpansionsPerLead = 64;  // tree expansions between two lead computations

// A node of the tree: the state after `control` from `parent`.
struct Motion {
  physics::PhysicsState state;
  Vec2 robot = Vec2::Zero();
  int parent = -1;
  Control control;
  int automaton_state = 0;
  int product_state = 0;
};

// Kappa is a function of the movable bodies' poses only, which stay bit for bit the same while the robot
// moves without pushing: then INFERENCE need not run again.
bool same_poses(const std::vector<geometry::Pose2>& a, const std::vector<geometry::Pose2>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const geometry::Pose2& p, const geometry::Pose2& q) {
    return p.position == q.position && p.yaw == q.yaw;
  });
}

// Uniform point in a triangle.
Vec2 point_in(const decomposition::Triangle& t, Random& random) {
  double a = random.uniform01(), b = random.uniform01();
  if (a + b > 1.0) a = 1.0 - a, b = 1.0 - b;
  return t.corners[0] + a * (t.corners[1] - t.corners[0]) + b * (t.corners[2] - t.corners[0]);
}

class Search {
 public:
  Search(const scenario::World& world, const TaskAutomaton& task, const knowledge::AbstractKnowledge& knowledge,
         const decomposition::Decomposition& decomposition, const PlannerOptions& options)
      : world_(world),
        task_(task),
        knowledge_(knowledge),
        decomposition_(decomposition),
        options_(options),
        mode_(validity_mode(options.guidance)),
        graph_(decomposition, task),
        sampler_(world, knowledge, options.guidance == Guidance::kKnowledge),
        random_(options.seed),
        simulation_(world),
        regions_(world) {}

  PlanResult run() {
    const auto started = std::chrono::steady_clock::now();
    PlanResult result;
    add_root();
    const int root_product = motions_[0].product_state;
    if (task_.dfa.accepting[motions_[0].automaton_state]) {
      finish(result, 0, started, "solved");
      return result;
    }
    while (true) {
      if (const char* reason = should_stop(started)) {
        finish(result, -1, started, reason);
        return result;
      }
      const std::vector<int> lead = graph_.lead(root_product);
      if (lead.empty()) {
        finish(result, -1, started, "no lead");
        return result;
      }
      collect_available(lead);
      for (int i = 0; i < kExpansionsPerLead && !available_.empty(); ++i) {
        const int solution = expand(lead);
        if (solution >= 0) {
          finish(result, solution, started, "solved");
          return result;
        }
      }
    }
  }

 private:
  const char* should_stop(std::chrono::steady_clock::time_point started) const {
    if (options_.stop != nullptr && options_.stop->load(std::memory_order_relaxed)) return "interrupted";
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count() >= options_.time_limit) {
      return "time limit";
    }
    if (motions_.size() >= options_.max_tree_nodes) return "tree full";
    return nullptr;
  }

  void add_root() {
    simulation_.reset();
    Motion root;
    simulation_.save(root.state);
    root.robot = world_.robot.start;
    // The start is labelled with its region too (OMPL's LTLPlanner forgets this).
    root.automaton_state = task_.step(task_.dfa.start, regions_.at(root.robot));
    root.product_state = graph_.id(decomposition_.locate(root.robot), root.automaton_state);
    motions_.push_back(std::move(root));
    graph_.add_motion(motions_[0].product_state, 0);
  }

  // Lead states that already hold tree nodes, with their weights, for sampling where to grow.
  void collect_available(const std::vector<int>& lead) {
    available_.clear();
    cumulative_.clear();
    double total = 0.0;
    for (size_t i = 0; i < lead.size(); ++i) {
      if (graph_.motions(lead[i]).empty()) continue;
      total += graph_.weight(lead[i]);
      available_.push_back(static_cast<int>(i));
      cumulative_.push_back(total);
    }
  }

  int pick_available_lead_index() {
    const double x = random_.uniform01() * cumulative_.back();
    const size_t k = std::upper_bound(cumulative_.begin(), cumulative_.end(), x) - cumulative_.begin();
    return available_[std::min(k, available_.size() - 1)];
  }

  // One SelectHighLevelState / SampleControlAndSteps / propagate round. Returns the index of a motion
  // that reached acceptance, or -1.
  int expand(const std::vector<int>& lead) {
    const int lead_index = pick_available_lead_index();
    const int product = lead[lead_index];
    graph_.count_selection(product);
    const auto& candidates = graph_.motions(product);
    const int from = candidates[random_.uniform_int(0, static_cast<int>(candidates.size()) - 1)];

    // Aim a few lead steps ahead: one triangle is too short a horizon for a robot pushing a box.
    const int ahead = std::min<int>(lead_index + random_.uniform_int(1, 4), static_cast<int>(lead.size()) - 1);
    const Vec2 target = point_in(decomposition_.triangles()[graph_.triangle_of(lead[ahead])], random_);

    simulation_.restore(motions_[from].state);
    simulation_.read_environment(environment_);
    update_kappa();
    const Control control = sampler_.sample(environment_, kappa_, target, random_);
    ++stats_.propagations;

    int automaton_state = motions_[from].automaton_state;
    int valid_steps = 0;
    bool accepted = false;
    for (int step = 1; step <= control.steps; ++step) {
      simulation_.step(control.force, contacts_);
      ++stats_.physics_steps;
      simulation_.read_environment(environment_);
      // VALIDITYCHECKER(E_new, kappa_j), then kappa_{j+1} = INFERENCE(E_new, kappa_j).
      if (!knowledge::is_valid(knowledge_, kappa_, environment_, contacts_, mode_)) {
        ++stats_.invalid_steps;
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
    if (valid_steps == 0) return -1;

    Motion motion;
    motion.state = last_valid_;
    motion.robot = Vec2(last_valid_.values[0], last_valid_.values[1]);  // the robot's x, y come first
    motion.parent = from;
    motion.control = {control.force, valid_steps};
    motion.automaton_state = automaton_state;
    motion.product_state = graph_.id(decomposition_.locate(motion.robot), automaton_state);
    const int index = static_cast<int>(motions_.size());
    graph_.add_motion(motion.product_state, index);
    motions_.push_back(std::move(motion));
    return accepted ? index : -1;
  }

  // kappa_ = INFERENCE(environment_), skipped when no movable body moved since the last inference.
  void update_kappa() {
    if (kappa_valid_ && same_poses(environment_.movable_poses, kappa_poses_)) return;
    knowledge::infer(knowledge_, environment_, kappa_);
    kappa_poses_ = environment_.movable_poses;
    kappa_valid_ = true;
  }

  void finish(PlanResult& result, int solution, std::chrono::steady_clock::time_point started, const char* reason) {
    result.solved = solution >= 0;
    result.stop_reason = reason;
    for (int m = solution; m > 0; m = motions_[m].parent) {
      result.plan.controls.push_back(motions_[m].control);
      result.plan.states.push_back(motions_[m].state);
    }
    std::reverse(result.plan.controls.begin(), result.plan.controls.end());
    std::reverse(result.plan.states.begin(), result.plan.states.end());
    result.tree.reserve(motions_.size());
    for (size_t m = 1; m < motions_.size(); ++m) {
      result.tree.push_back({motions_[motions_[m].parent].robot, motions_[m].robot, motions_[m].automaton_state});
    }
    stats_.tree_nodes = static_cast<long long>(motions_.size());
    stats_.planning_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    result.stats = stats_;
  }

  const scenario::World& world_;
  const TaskAutomaton& task_;
  const knowledge::AbstractKnowledge& knowledge_;
  const decomposition::Decomposition& decomposition_;
  const PlannerOptions& options_;
  const knowledge::ValidityMode mode_;
  ProductGraph graph_;
  ControlSampler sampler_;
  Random random_;
  physics::Simulation simulation_;
  const RegionMap regions_;
  std::vector<Motion> motions_;
  std::vector<int> available_;         // indices into the current lead
  std::vector<double> cumulative_;     // running sums of their weights
  PlannerStats stats_;
  // Scratch space reused by every step, so the hot loop does not allocate.
  scenario::EnvironmentState environment_;
  knowledge::Kappa kappa_;
  std::vector<geometry::Pose2> kappa_poses_;  // the poses kappa_ was inferred for
  bool kappa_valid_ = false;
  std::vector<scenario::RobotContact> contacts_;
  physics::PhysicsState last_valid_;
};

}  // namespace

knowledge::ValidityMode validity_mode(Guidance guidance) {
  return guidance == Guidance::kKnowledge ? knowledge::ValidityMode::kKnowledge : knowledge::ValidityMode::kBaseline;
}

PlanResult plan(const scenario::World& world, const TaskAutomaton& task, const knowledge::AbstractKnowledge& knowledge,
                const decomposition::Decomposition& decomposition, const PlannerOptions& options) {
  return Search(world, task, knowledge, decomposition, options).run();
}

int Plan::total_steps() const {
  int total = 0;
  for (const auto& c : controls) total += c.steps;
  return total;
}

}  // namespace physltl::planning
