#include "physltl/planning/planner.h"

#include "lead_search.h"
#include "ompl_planner.h"
#include "product_graph.h"
#include "random.h"
#include "tree_grower.h"
#include "worker_pool.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <functional>
#include <optional>

namespace physltl::planning {
namespace {

constexpr int kExpansionsPerLead = 64;  // tree expansions between two lead computations
// Expansions chosen together and grown in parallel. Choosing a batch before growing it makes the plan
// independent of the number of threads; a batch much larger than the thread count keeps them all busy
// although its propagations differ in length.
constexpr int kBatch = 16;
static_assert(kExpansionsPerLead % kBatch == 0);
constexpr int kBatchesPerLead = kExpansionsPerLead / kBatch;
// Share of expansions that grow from the frontier of the lead (below) rather than from anywhere along it.
// Bhatia's weights alone spread the effort over every stage the tree has passed, most of it going to
// rooms already done in a sequencing task; the rest keeps every stage in reach. Measured with the next
// constant (median propagations, seeds 1..12/8/12/10/10): rooms_n with 4, 8 and 16 rooms 42 %, 29 % and
// 46 % fewer, rooms.lua 13 % and ordered.lua 45 % fewer.
constexpr double kFrontierShare = 0.8;
// How many lead states ahead an expansion may aim: one triangle is too short a horizon for a robot
// pushing a box, and small triangles along walls make a few of them short too.
constexpr int kMaxStepsAhead = 8;
// A node whose expansions fail at their first physics step this many times in a row is dropped from the
// candidates: the robot is about to hit a wall or a box's forbidden side whatever it does. Such nodes are
// common, since a motion keeps the valid steps before the one that failed, and when they were the only
// ones in the lead's frontier they held the search for thousands of expansions (rooms_n with 16 rooms,
// seeds 1..12: median propagations 21,700 -> 17,600, worst 65,600 -> 23,900; 2, 4 and 8 within noise of
// each other; rooms.lua and ordered.lua unchanged).
constexpr int kFailuresBeforeDropped = 8;
// The lead ends this many automaton steps beyond the furthest the tree has got, not at acceptance: the
// expansions only use its first part, and with many stages ahead the rest was most of the lead search's
// work (rooms_n with 16 rooms: the same leads in 8 of 10 seeds, no more propagations; one step ahead
// changed most leads and cost 20 % more).
constexpr int kLevelsAhead = 2;

// Where to grow from and towards, and the seed of the grower's own generator.
struct Expansion {
  int from = 0;
  Vec2 target = Vec2::Zero();
  std::uint64_t seed = 0;
};

// The knowledge planner's lead goes round boxes that stand in the open: a triangle where the robot's
// centre would overlap such a box, as the World places it, weighs kObstructedWeight in the lead search, so
// the lead takes the aisles beside a box rather than a way through it. A box with a fixed body within
// the robot's diameter stands in a passage (a doorway, a corridor) and is not avoided: the way through is
// usually the only way, and pushing it is what the task needs. Boxes move while planning; the weights
// keep their first places: cheap, and the tree's own statistics take over where the lead was wrong.
constexpr double kObstructedWeight = 0.1;

std::vector<double> clearance_weights(const decomposition::Decomposition& decomposition,
                                      const knowledge::AbstractKnowledge& knowledge) {
  const double r = knowledge.robot.radius;
  std::vector<geometry::OrientedBox> in_the_open;
  for (const auto& b : knowledge.movable_bodies) {
    const geometry::OrientedBox reach{b.footprint.pose, b.footprint.half_extents + geometry::Vec2::Constant(2 * r)};
    const bool in_a_passage = std::any_of(knowledge.fixed_bodies.begin(), knowledge.fixed_bodies.end(),
                                          [&](const auto& f) { return geometry::overlap(reach, f.footprint); });
    if (!in_a_passage) in_the_open.push_back(b.footprint);
  }
  std::vector<double> weights;
  weights.reserve(decomposition.triangles().size());
  for (const auto& triangle : decomposition.triangles()) {
    const bool obstructed = std::any_of(in_the_open.begin(), in_the_open.end(), [&](const geometry::OrientedBox& box) {
      return geometry::overlap(box, triangle.centroid, r);
    });
    weights.push_back(obstructed ? kObstructedWeight : 1.0);
  }
  return weights;
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
        triangle_weights_(options.planner == PlannerKind::kKnowledge ? clearance_weights(decomposition, knowledge)
                                                                   : std::vector<double>{}),
        graph_(decomposition, task, triangle_weights_),
        lead_search_(graph_),
        random_(options.seed),
        pool_(options.threads),
        growers_(static_cast<size_t>(pool_.threads())) {}

  PlanResult run() {
    const auto started = std::chrono::steady_clock::now();
    PlanResult result;
    add_root();
    const int root_product = motions_[0].product_state;
    if (task_.dfa.accepting[motions_[0].automaton_state]) {
      finish(result, 0, started, "solved");
      return result;
    }
    std::vector<int> lead = lead_search_.next(root_product, horizon());
    while (true) {
      if (lead.empty()) {
        finish(result, -1, started, "no lead");
        return result;
      }
      std::vector<int> next_lead;
      for (int batch = 0; batch < kBatchesPerLead; ++batch) {
        // Again for every batch: the last one may have added nodes to the lead or dropped some.
        collect_available(lead);
        choose_expansions(lead);
        // The next lead is computed while the last batch grows: the tree stands still meanwhile, and on a
        // large world the lead search costs as much as a batch.
        if (batch + 1 == kBatchesPerLead) {
          grow_in_parallel([&, horizon = horizon()] { next_lead = lead_search_.next(root_product, horizon); });
        } else {
          grow_in_parallel(nullptr);
        }
        const int solution = add_growths();
        if (solution >= 0) {
          finish(result, solution, started, "solved");
          return result;
        }
        if (const char* reason = should_stop(started)) {
          finish(result, -1, started, reason);
          return result;
        }
      }
      lead = std::move(next_lead);
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

  // How far the lead looks: a few automaton steps beyond the furthest the tree has got.
  int horizon() const { return std::max(0, closest_to_accept_ - kLevelsAhead); }

  void add_root() {
    physics::Simulation simulation(world_);
    const RegionMap regions(world_);
    Motion root;
    simulation.save(root.state);
    root.robot = world_.robot.start;
    // The start is labelled with its region too (OMPL's LTLPlanner forgets this).
    root.automaton_state = task_.step(task_.dfa.start, regions.at(root.robot));
    root.product_state = graph_.id(decomposition_.locate(root.robot), root.automaton_state);
    closest_to_accept_ = graph_.distance_to_accept(root.automaton_state);
    motions_.push_back(std::move(root));
    failed_starts_.push_back(0);
    graph_.add_motion(motions_[0].product_state, 0);
  }

  // Lead states that already hold tree nodes, with their weights, for sampling where to grow.
  // The frontier: the available lead states in the automaton state of the last one, the furthest the tree
  // has got along the lead.
  void collect_available(const std::vector<int>& lead) {
    available_.clear();
    cumulative_.clear();
    double total = 0.0;
    int frontier_automaton_state = -1;
    for (size_t i = 0; i < lead.size(); ++i) {
      if (graph_.motions(lead[i]).empty()) continue;
      const int q = graph_.automaton_state_of(lead[i]);
      if (q != frontier_automaton_state) frontier_automaton_state = q, frontier_weight_ = total;
      total += graph_.weight(lead[i]);
      available_.push_back(static_cast<int>(i));
      cumulative_.push_back(total);
    }
  }

  // By weight among the available lead states: usually those of the frontier, sometimes all of them.
  int pick_available_lead_index() {
    const double from = random_.chance(kFrontierShare) ? frontier_weight_ : 0.0;
    const double x = from + random_.uniform01() * (cumulative_.back() - from);
    const size_t k = std::upper_bound(cumulative_.begin(), cumulative_.end(), x) - cumulative_.begin();
    return available_[std::min(k, available_.size() - 1)];
  }

  // SelectHighLevelState of Algorithm 3, kBatch times, with the tree as it stands.
  void choose_expansions(const std::vector<int>& lead) {
    expansions_.resize(kBatch);
    for (Expansion& e : expansions_) {
      const int lead_index = pick_available_lead_index();
      const int product = lead[lead_index];
      graph_.count_selection(product);
      const auto& candidates = graph_.motions(product);
      e.from = candidates[random_.uniform_int(0, static_cast<int>(candidates.size()) - 1)];
      const int ahead =
          std::min<int>(lead_index + random_.uniform_int(1, kMaxStepsAhead), static_cast<int>(lead.size()) - 1);
      const double u = random_.uniform01(), v = random_.uniform01();
      e.target = decomposition_.triangles()[graph_.triangle_of(lead[ahead])].point_at(u, v);
      e.seed = random_.next();
    }
  }

  // SampleControlAndSteps and propagation for the whole batch. The tree is only read meanwhile.
  // `alongside`, if given, runs as one more task of the batch, first.
  void grow_in_parallel(const std::function<void()>& alongside) {
    growths_.resize(expansions_.size());
    const int extra = alongside ? 1 : 0;
    pool_.run(static_cast<int>(expansions_.size()) + extra, [&](int worker, int task) {
      if (task < extra) return alongside();
      // Built on the thread that uses it: ODE keeps per-thread data.
      auto& grower = growers_[static_cast<size_t>(worker)];
      if (!grower) grower.emplace(world_, task_, knowledge_, decomposition_, graph_, options_.planner == PlannerKind::kKnowledge);
      const Expansion& e = expansions_[static_cast<size_t>(task - extra)];
      grower->grow(motions_[static_cast<size_t>(e.from)], e.target, e.seed, growths_[static_cast<size_t>(task - extra)]);
    });
  }

  // Adds the batch's motions in the order the expansions were chosen. Returns the first motion that
  // reached acceptance, or -1.
  int add_growths() {
    for (size_t i = 0; i < growths_.size(); ++i) {
      Growth& growth = growths_[i];
      ++stats_.propagations;
      stats_.physics_steps += growth.physics_steps;
      stats_.invalid_steps += growth.stopped_by_invalid_step ? 1 : 0;
      note_outcome(expansions_[i].from, growth);
      if (!growth.motion) continue;
      const int index = static_cast<int>(motions_.size());
      growth.motion->parent = expansions_[i].from;
      graph_.add_motion(growth.motion->product_state, index);
      closest_to_accept_ = std::min(closest_to_accept_, graph_.distance_to_accept(growth.motion->automaton_state));
      motions_.push_back(std::move(*growth.motion));
      failed_starts_.push_back(0);
      if (growth.accepted && growth.braking) {
        growth.braking->parent = index;
        motions_.push_back(std::move(*growth.braking));
        failed_starts_.push_back(0);
        return index + 1;
      }
      if (growth.accepted) return index;
    }
    return -1;
  }

  void note_outcome(int from, const Growth& growth) {
    int& failures = failed_starts_[static_cast<size_t>(from)];
    if (growth.motion || !growth.stopped_by_invalid_step) {
      failures = 0;
      return;
    }
    // The root stays: it keeps the search going, and a robot at rest can always move.
    if (++failures == kFailuresBeforeDropped && from != 0) {
      graph_.remove_motion(motions_[static_cast<size_t>(from)].product_state, from);
    }
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
  const std::vector<double> triangle_weights_;  // the knowledge planner's: the lead goes round boxes
  ProductGraph graph_;
  LeadSearch lead_search_;
  Random random_;
  std::vector<Motion> motions_;
  int closest_to_accept_ = 0;             // fewest automaton steps to acceptance from any node
  std::vector<int> failed_starts_;        // per motion: expansions in a row that failed at once
  std::vector<int> available_;         // indices into the current lead
  std::vector<double> cumulative_;     // running sums of their weights
  double frontier_weight_ = 0.0;       // the running sum where the frontier starts
  std::vector<Expansion> expansions_;  // the current batch
  std::vector<Growth> growths_;        // what each of them grew
  PlannerStats stats_;
  WorkerPool pool_;
  std::vector<std::optional<TreeGrower>> growers_;  // one per worker
};

}  // namespace

namespace {

constexpr std::array<std::pair<PlannerKind, const char*>, 7> kPlannerNames = {{
    {PlannerKind::kKnowledge, "knowledge"},
    {PlannerKind::kBaseline, "baseline"},
    {PlannerKind::kOmplLtl, "ompl-ltl"},
    {PlannerKind::kOmplRrt, "ompl-rrt"},
    {PlannerKind::kOmplKpiece, "ompl-kpiece"},
    {PlannerKind::kOmplSst, "ompl-sst"},
    {PlannerKind::kOmplPdst, "ompl-pdst"},
}};

}  // namespace

const char* planner_name(PlannerKind planner) {
  for (const auto& [kind, name] : kPlannerNames) {
    if (kind == planner) return name;
  }
  return "?";
}

std::optional<PlannerKind> planner_from_name(std::string_view name) {
  for (const auto& [kind, known] : kPlannerNames) {
    if (name == known) return kind;
  }
  return std::nullopt;
}

const std::vector<PlannerKind>& all_planners() {
  static const std::vector<PlannerKind> planners = [] {
    std::vector<PlannerKind> all;
    for (const auto& entry : kPlannerNames) all.push_back(entry.first);
    return all;
  }();
  return planners;
}

bool is_ompl(PlannerKind planner) { return planner != PlannerKind::kKnowledge && planner != PlannerKind::kBaseline; }

std::optional<std::string> refusal(PlannerKind planner, const TaskAutomaton& task) {
  if (!is_ompl(planner) || !task.ends_at_rest()) return std::nullopt;
  return std::string(planner_name(planner)) + " plans co-safe tasks only (OMPL's product graph takes co-safe tasks, " +
         "and co-safe with safety, satisfied by a finite run), but this task is satisfied only by a plan that ends at " +
         "rest: plan it with knowledge or baseline";
}

knowledge::ValidityMode validity_mode(PlannerKind planner) {
  return planner == PlannerKind::kBaseline ? knowledge::ValidityMode::kBaseline : knowledge::ValidityMode::kKnowledge;
}

PlanResult plan(const scenario::World& world, const TaskAutomaton& task, const knowledge::AbstractKnowledge& knowledge,
                const decomposition::Decomposition& decomposition, const PlannerOptions& options) {
  if (is_ompl(options.planner)) return plan_with_ompl(world, task, knowledge, decomposition, options);
  return Search(world, task, knowledge, decomposition, options).run();
}

int Plan::total_steps() const {
  int total = 0;
  for (const auto& c : controls) total += c.steps;
  return total;
}

}  // namespace physltl::planning
