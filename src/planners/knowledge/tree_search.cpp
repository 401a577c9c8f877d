#include "tree_search.h"

#include "lead_search.h"
#include "object_lead.h"
#include "product_graph.h"
#include "push_plan_lead.h"
#include "physltl/planning/random.h"
#include "physltl/planning/stage_graph.h"
#include "tree_grower.h"
#include "worker_pool.h"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <set>
#include <cstdio>
#include <array>
#include <atomic>
#include <chrono>
#include <functional>
#include <limits>
#include <optional>

namespace physltl::planners::knowledge {

using geometry::Vec2;

namespace {

// The tree's memory bound: ~0.5 KiB per node.
constexpr std::size_t kMaxTreeNodes = 2'000'000;
constexpr int kExpansionsPerLead = 64;  // tree expansions between two lead computations
// Expansions chosen together and grown in parallel. Choosing a batch before growing it makes the plan
// independent of the number of threads; a batch much larger than the thread count keeps them all busy
// although its propagations differ in length.
constexpr int kBatch = 16;
static_assert(kExpansionsPerLead % kBatch == 0);
constexpr int kBatchesPerLead = kExpansionsPerLead / kBatch;
// Share of expansions that grow from the frontier of the lead (below) rather than from anywhere along it.
// Bhatia's weights alone spread the effort over every stage the tree has passed, most of it going to
// rooms already done in a sequencing task; the rest keeps every stage in reach (measured: docs/benchmarks.md, "The tree search's constants").
constexpr double kFrontierShare = 0.8;
// At most this many of the frontier stage's lead states, the furthest along, make the frontier: a stage
// that crosses a large world (the 6,400-box warehouse's first lane, 95 m, some 160 lead states) otherwise
// spread its expansions over all the ground it had covered. Above what the shipped scenarios, the
// regression family and the puzzles reach (docs/benchmarks.md, "The tree search's constants").
constexpr std::ptrdiff_t kMaxFrontierStates = 64;
// How many lead states ahead an expansion may aim: one triangle is too short a horizon for a robot
// pushing a box, and small triangles along walls make a few of them short too.
constexpr int kMaxStepsAhead = 8;
// A node whose expansions fail at their first physics step this many times in a row is dropped from the
// candidates: the robot is about to hit a wall or a box's forbidden side whatever it does. Such nodes are
// common, since a motion keeps the valid steps before the one that failed, and when they were the only
// ones in the lead's frontier they held the search for thousands of expansions (docs/benchmarks.md, "The tree search's constants").
constexpr int kFailuresBeforeDropped = 8;
// The lead ends this many automaton steps beyond the furthest the tree has got, not at acceptance: the
// expansions only use its first part, and with many stages ahead the rest was most of the lead search's
// work (docs/benchmarks.md, "The tree search's constants").
constexpr int kLevelsAhead = 2;

// Where a stage needs a body moved, the expansions go to the frontier stage's nodes whose body is nearest
// its goal along its way (the best of a few drawn at random), and sometimes to any of them: the nearest
// nodes are where the body is pushed on, the others keep a stuck body from holding the search. A node's
// distance counts the robot's way to the body a little, and each time it was chosen already.
constexpr double kObjectNearestShare = 0.8;
constexpr int kObjectTournament = 4;
constexpr double kObjectRobotWeight = 0.3;       // per metre between the robot and the body
constexpr double kObjectSelectionPenalty = 0.2;  // metres per earlier choice of the node

// The escape from the knowledge planner's heuristics (docs/planner.md, "Cuts and biases"): once this many
// expansions have passed without a node getting closer to acceptance, kWidenedShare of the expansions
// grow as the baseline grows them (a uniform control, no route-choice cut), half of them from any node
// of the tree, dropped ones included. Given time, whatever the baseline's search can grow, these can.
constexpr long long kStallExpansions = 4096;
constexpr double kWidenedShare = 0.25;
constexpr double kWidenedAnywhereShare = 0.5;

// The look-ahead's order (push_plan_lead.h): once this many expansions have passed without a node getting
// further along it, the order is planned again from the latest node the physics left off it, at most
// kMaxReplans times; a new order must be found within kReplanArrangements. Half the widening's stall, so
// that the order is repaired before the search widens.
constexpr long long kReplanExpansions = kStallExpansions / 2;
constexpr int kMaxReplans = 8;
constexpr long long kReplanArrangements = 100'000;

// Where to grow from and towards, and the seed of the grower's own generator. With an object goal, the
// grower finds the target in the node's state (object_lead.h).
struct Expansion {
  int from = 0;
  Vec2 target = Vec2::Zero();
  std::optional<ObjectLead::Goal> goal;
  Guidance guidance = Guidance::kPushing;
  int push = -1;  // following the order: the push of it the node stands at
  std::uint64_t seed = 0;
};

class Search {
 public:
  Search(const planning::Problem& problem, const KnowledgePreparation* prepared, const planning::PlannerOptions& options, TreeSearchMode mode)
      : world_(problem.world),
        task_(problem.task),
        knowledge_(problem.knowledge),
        decomposition_(problem.decomposition),
        options_(options),
        knowledge_mode_(mode == TreeSearchMode::kKnowledge),
        primitives_(options.parameter(push_primitives_parameter()) == "on"),
        stage_graph_(prepared != nullptr && prepared->stages ? prepared->stages : std::make_shared<const planning::StageGraph>(task_)),
        stages_(*stage_graph_),
        // The knowledge planner's lead goes round the bodies where the task needs no pushing (route_choice.h).
        routes_(!knowledge_mode_       ? RouteChoice{}
                : prepared != nullptr ? prepared->routes
                                      : choose_routes(world_, task_, stages_, decomposition_)),
        graph_(decomposition_, stages_, routes_.lead_factor),
        lead_search_(graph_),
        object_lead_(world_, knowledge_, decomposition_),
        random_(options.seed),
        pool_(options.threads),
        growers_(static_cast<size_t>(pool_.threads())),
        stage_motions_(static_cast<size_t>(stages_.stages())),
        stage_nodes_(static_cast<size_t>(stages_.stages()), 0),
        stage_dropped_(static_cast<size_t>(stages_.stages()), 0) {
    if (knowledge_mode_ && prepared != nullptr && prepared->lookahead.plan.found) {
      lookahead_ = &prepared->lookahead;
      order_steps_ = lookahead_->steps;
      push_lead_.emplace(*lookahead_->lattice, lookahead_->start_cells, order_steps_, knowledge_);
    }
  }

  // `started`: when planning began, before this search prepared its lead (the route choice costs time too).
  planning::PlanResult run(std::chrono::steady_clock::time_point started) {
    planning::PlanResult result;
    add_root();
    if (accepting(motions_[0].stage)) {
      finish(result, 0, started, planning::StopReason::kSolved);
      return result;
    }
    int lead_start = segment_start_;
    std::vector<int> lead = lead_search_.next(product_of(lead_start), horizon());
    current_lead_ = &lead;
    while (true) {
      // Where the frontier's next move is a body's, the object lead guides the expansions; else the lead
      // through the decomposition, from the first node after the last body the tree moved for the task.
      const std::optional<planning::BodyMove> body_move = stages_.body_move(frontier_stage_);
      if (!body_move && lead_start != segment_start_) {
        lead_start = segment_start_;
        lead = lead_search_.next(product_of(lead_start), horizon());
      }
      if (!body_move && lead.empty()) {
        finish(result, -1, started, planning::StopReason::kNoLead);
        return result;
      }
      std::vector<int> next_lead;
      bool lead_kept = true;
      for (int batch = 0; batch < kBatchesPerLead; ++batch) {
        if (body_move && push_lead_) {
          choose_push_expansions(*body_move);
        } else if (body_move) {
          choose_object_expansions(*body_move);
        } else {
          // Again for every batch: the last one may have added nodes to the lead or dropped some. With
          // every node along it dropped, a new lead from the frontier's first node, which holds one.
          collect_available(lead);
          if (available_.empty()) {
            lead_kept = false;
            break;
          }
          choose_expansions(lead);
        }
        // The next lead is computed while the last batch grows: the tree stands still meanwhile, and on a
        // large world the lead search costs as much as a batch.
        if (batch + 1 == kBatchesPerLead) {
          grow_in_parallel([&, horizon = horizon(), start = product_of(lead_start)] {
            next_lead = lead_search_.next(start, horizon);
          });
        } else {
          grow_in_parallel(nullptr);
        }
        const int solution = add_growths();
        if (solution >= 0) {
          finish(result, solution, started, planning::StopReason::kSolved);
          return result;
        }
        if (const std::optional<planning::StopReason> reason = should_stop()) {
          finish(result, -1, started, *reason);
          return result;
        }
      }
      if (lead_kept) {
        lead = std::move(next_lead);
      } else {
        lead_start = segment_start_;
        lead = lead_search_.next(product_of(lead_start), horizon());
      }
    }
  }

 private:
  std::optional<planning::StopReason> should_stop() const {
    if (options_.deadline.reached()) return planning::stop_reason_of(options_.deadline);
    if (motions_.size() >= kMaxTreeNodes) return planning::StopReason::kTreeFull;
    if (options_.max_propagations > 0 && stats_.propagations >= options_.max_propagations) return planning::StopReason::kBudget;
    return std::nullopt;
  }

  // How far the lead looks: a few stages beyond the furthest the tree has got.
  int horizon() const { return std::max(0, closest_to_accept_ - kLevelsAhead); }
  bool accepting(int stage) const { return task_.dfa.accepting[static_cast<size_t>(stages_.automaton_state_of(stage))]; }
  int product_of(int motion) const { return motions_[static_cast<size_t>(motion)].product_state; }
  bool goes_round(int stage) const { return !routes_.going_round.empty() && routes_.going_round[static_cast<size_t>(stage)]; }

  void add_root() {
    physics::Simulation simulation(world_);
    Motion root;
    simulation.save(root.state);
    root.robot = world_.robot.start;
    // The start is labelled with its letter too (OMPL's LTLPlanner forgets this).
    const int letter = task_.labelling.letter(scenario::EnvironmentState::initial(world_));
    root.stage = stages_.stage(task_.step(task_.dfa.start, letter), task_.labelling.facts_of(letter));
    root.product_state = graph_.id(decomposition_.locate(root.robot), root.stage);
    closest_to_accept_ = stages_.distance(root.stage);
    frontier_stage_ = root.stage;
    add_motion(std::move(root));
  }

  // Adds a node to the tree and its book-keeping.
  void add_motion(Motion motion) {
    const int index = static_cast<int>(motions_.size());
    graph_.add_motion(motion.product_state, index);
    stage_motions_[static_cast<size_t>(motion.stage)].push_back(index);
    const int distance = stages_.distance(motion.stage);
    if (distance >= 0 && distance < closest_to_accept_) {
      // Out of a stage where a body had to move: the robot's part of the task starts again from here.
      if (stages_.body_move(frontier_stage_)) segment_start_ = index;
      closest_to_accept_ = distance;
      frontier_stage_ = motion.stage;
      expansions_since_progress_ = 0;
      fewest_lead_states_left_ = std::numeric_limits<int>::max();
    }
    if (stage_nodes_[static_cast<size_t>(motion.stage)]++ == 0) stages_reached_.push_back(motion.stage);
    failed_starts_.push_back(0);
    chosen_.push_back(0);
    primitive_tried_.push_back(false);
    dropped_.push_back(false);
    note_push_progress(motion);
    motions_.push_back(std::move(motion));
  }

  // Lead states that already hold tree nodes, with their weights, for sampling where to grow.
  // The frontier: the available lead states in the automaton state of the last one, the furthest the tree
  // has got along the lead.
  void collect_available(const std::vector<int>& lead) {
    available_.clear();
    cumulative_.clear();
    double total = 0.0;
    int frontier = -1;  // the stage of the frontier
    for (size_t i = 0; i < lead.size(); ++i) {
      if (graph_.motions(lead[i]).empty()) continue;
      const int q = graph_.stage_of(lead[i]);
      if (q != frontier) frontier = q, frontier_weight_ = total;
      total += graph_.weight(lead[i]);
      available_.push_back(static_cast<int>(i));
      cumulative_.push_back(total);
    }
    if (available_.empty()) return;
    // A stage that crosses a large world: its frontier is the part furthest along the lead.
    const auto first_in_frontier = std::upper_bound(cumulative_.begin(), cumulative_.end(), frontier_weight_);
    if (cumulative_.end() - first_in_frontier > kMaxFrontierStates) {
      frontier_weight_ = *(cumulative_.end() - kMaxFrontierStates - 1);
    }
    // Within a stage, fewer lead states left after the furthest node than ever in the stage is progress
    // too: such a stage takes more than a stall's expansions to cross, and widening there only spread the
    // effort. (The lead is recomputed, so a shorter new one counts as well; the least count only goes down.)
    const int left = static_cast<int>(lead.size()) - 1 - available_.back();
    if (left < fewest_lead_states_left_) {
      fewest_lead_states_left_ = left;
      expansions_since_progress_ = 0;
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
      e.goal.reset();
      e.guidance = goes_round(motions_[static_cast<size_t>(e.from)].stage) ? Guidance::kGoingRound : Guidance::kPushing;
      widen_if_stalled(e);
      e.seed = random_.next();
    }
  }

  // Past a stall, some expansions grow as the baseline's would, some of those from anywhere in the tree.
  void widen_if_stalled(Expansion& e) {
    if (next_expansion_widened()) widen(e);
  }
  // Counts one more expansion towards the stall; past it, whether this one is of the widened share.
  bool next_expansion_widened() {
    ++expansions_since_progress_;
    if (!knowledge_mode_ || expansions_since_progress_ < kStallExpansions) return false;
    widened_ = true;
    return random_.chance(kWidenedShare);
  }
  void widen(Expansion& e) {
    e.guidance = Guidance::kWidened;
    e.goal.reset();
    if (random_.chance(kWidenedAnywhereShare)) e.from = random_.uniform_int(0, static_cast<int>(motions_.size()) - 1);
  }

  // Where a body's centre is in the state of node `motion`.
  Vec2 body_at(int motion, int body) const {
    const physics::PhysicsState& state = motions_[static_cast<size_t>(motion)].state;
    const auto b = static_cast<size_t>(body) + 1;  // the robot is body 0
    return {state.value(b, 0), state.value(b, 1)};
  }

  // The object lead's aim from node `e.from`: from afar along the decomposition towards the body, near it
  // the goal's target in the node's state.
  void aim_at_body(Expansion& e, const ObjectLead::Goal& goal) {
    const std::optional<Vec2> approach = object_lead_.approach(motions_[static_cast<size_t>(e.from)].robot, body_at(e.from, goal.body));
    e.target = approach.value_or(Vec2::Zero());
    e.goal = approach ? std::nullopt : std::optional<ObjectLead::Goal>(goal);
  }

  // The object lead's goal for `move` in the state of node `motion` (for a group: the body it pushes on).
  ObjectLead::Goal goal_at(int motion, const planning::BodyMove& move) {
    return object_lead_.goal(task_.labelling, move, [&](int body) { return body_at(motion, body); });
  }

  // The object lead's choice of a node to grow from for `move`: of the frontier stage's nodes, usually the
  // one whose body is nearest its goal along its way of a few drawn at random, sometimes any of them.
  int object_lead_node(const planning::BodyMove& move) {
    const std::vector<int>& nodes = object_lead_nodes(move);
    const auto distance = [&](int m) {
      const ObjectLead::Goal goal = goal_at(m, move);
      return ObjectLead::remaining(goal, body_at(m, goal.body)) +
             kObjectRobotWeight * (motions_[static_cast<size_t>(m)].robot - body_at(m, goal.body)).norm() +
             kObjectSelectionPenalty * chosen_[static_cast<size_t>(m)];
    };
    const auto any_node = [&] { return nodes[static_cast<size_t>(random_.uniform_int(0, static_cast<int>(nodes.size()) - 1))]; };
    int from = any_node();
    if (random_.chance(kObjectNearestShare)) {
      double nearest = distance(from);
      for (int i = 1; i < kObjectTournament; ++i) {
        const int other = any_node();
        const double d = distance(other);
        if (d < nearest) from = other, nearest = d;
      }
    }
    count_choice(from);
    return from;
  }

  // The nodes the object lead grows from for `move`: the frontier stage's; for a group's move, those of
  // them with the most bodies of the group where the move wants them. A group's bodies go one by one
  // within one stage, and each one placed is progress as a stage is (20 boxes a push above their goals:
  // no plan in 60 s when all the stage's nodes were drawn from).
  const std::vector<int>& object_lead_nodes(const planning::BodyMove& move) {
    const std::vector<int>& nodes = stage_motions_[static_cast<size_t>(frontier_stage_)];
    if (task_.labelling.named_parts()[static_cast<size_t>(move.named)].bodies.size() == 1) return nodes;
    GroupFrontier& g = group_frontier_;
    if (g.stage != frontier_stage_) g = GroupFrontier{frontier_stage_, 0, -1, {}};
    for (; g.known < nodes.size(); ++g.known) {
      const int m = nodes[g.known];
      const int placed = object_lead_.placed_bodies(task_.labelling, move, [&](int body) { return body_at(m, body); });
      if (placed > g.placed) g.placed = placed, g.nodes.clear();
      if (placed == g.placed) g.nodes.push_back(m);
    }
    return g.nodes;
  }
  struct GroupFrontier {
    int stage = -1;          // the frontier stage it is of
    std::size_t known = 0;   // that stage's nodes looked at so far
    int placed = -1;         // the most bodies placed in one of them
    std::vector<int> nodes;  // the nodes with that many
  };
  GroupFrontier group_frontier_;

  // The object lead's expansions, kBatch of them, for moving a body of the frontier stage.
  void choose_object_expansions(const planning::BodyMove& move) {
    expansions_.resize(kBatch);
    for (Expansion& e : expansions_) {
      e.from = object_lead_node(move);
      aim_at_body(e, goal_at(e.from, move));
      e.guidance = Guidance::kPushing;
      widen_if_stalled(e);
      e.seed = random_.next();
    }
  }

  // Where a new node stands on the look-ahead's order, from where its parent stood.
  void note_push_progress(const Motion& motion) {
    if (!push_lead_) return;
    const int hint = motion.parent >= 0 ? push_progress_[static_cast<size_t>(motion.parent)].push : 0;
    const PushPlanLead::Progress progress = push_lead_->progress(motion.state, hint);
    if (progress.remaining < best_push_remaining_) {
      best_push_remaining_ = progress.remaining;
      batches_since_push_progress_ = 0;
    }
    push_progress_.push_back(progress);
    furthest_push_ = std::max(furthest_push_, progress.push);
    rank_on_order(static_cast<int>(push_progress_.size()) - 1);
  }

  // Each choice of node `m` to grow from ranks it a little further back, on the order too.
  void count_choice(int m) {
    const bool ranked = push_lead_ && push_progress_[static_cast<size_t>(m)].push >= 0;
    if (ranked) ranked_on_order_.erase({order_rank(m), m});
    ++chosen_[static_cast<size_t>(m)];
    if (ranked) rank_on_order(m);
  }

  // Nodes on the order, best first: how much work is left, and a little more each time one was grown from.
  double order_rank(int m) const {
    return push_progress_[static_cast<size_t>(m)].remaining + kObjectSelectionPenalty * chosen_[static_cast<size_t>(m)];
  }
  void rank_on_order(int m) {
    if (push_progress_[static_cast<size_t>(m)].push >= 0) ranked_on_order_.insert({order_rank(m), m});
  }

  // The look-ahead's expansions, kBatch of them: from the frontier stage's nodes furthest along the push
  // order (the best of a few drawn at random), and sometimes from any of them. Where the order has no
  // target for a node (off the order, or its walk blocked), the object lead's.
  // Past a stall, the widened share of them grows where the baseline's search would, from the object
  // lead's nodes (object_lead_node): an order the physics cannot follow, or a way the lattice does not
  // know, must not keep the tree from what the baseline finds.
  void choose_push_expansions(const planning::BodyMove& move) {
    if (++batches_since_push_progress_ * kBatch >= kReplanExpansions) replan_pushes();
    const std::vector<int>& nodes = stage_motions_[static_cast<size_t>(frontier_stage_)];
    expansions_.resize(kBatch);
    for (Expansion& e : expansions_) {
      if (next_expansion_widened()) {
        e.from = object_lead_node(move);
        widen(e);
        e.seed = random_.next();
        continue;
      }
      int from = nodes[static_cast<size_t>(random_.uniform_int(0, static_cast<int>(nodes.size()) - 1))];
      const bool best = !ranked_on_order_.empty() && random_.chance(kObjectNearestShare);
      if (best) from = ranked_on_order_.begin()->second;
      count_choice(from);
      e.from = from;
      e.seed = random_.next();
      const int push = push_progress_[static_cast<size_t>(from)].push;
      if (primitives_ && push >= 0 && !primitive_tried_[static_cast<size_t>(from)]) {
        // The order carried out by the push primitive, once from each node on it.
        primitive_tried_[static_cast<size_t>(from)] = true;
        e.guidance = Guidance::kFollowingOrder;
        e.push = push;
        continue;
      }
      e.guidance = Guidance::kPushing;
      const Motion& node = motions_[static_cast<size_t>(from)];
      if (const auto target = push_lead_->target(node.state, push)) {
        e.target = target->point;
        e.goal.reset();
        e.guidance = Guidance::kPushingTo;
      } else {
        aim_at_body(e, goal_at(from, move));
      }
    }
  }

  // A new push order from the latest node of the frontier stage that the physics left off the order with
  // every body on a lattice place; the nodes' places on it found again.
  void replan_pushes() {
    batches_since_push_progress_ = 0;
    if (lookahead_replans_ >= kMaxReplans) return;
    const lookahead::PushLattice& lattice = *lookahead_->lattice;
    const std::vector<int>& nodes = stage_motions_[static_cast<size_t>(frontier_stage_)];
    for (auto it = nodes.rbegin(); it != nodes.rend(); ++it) {
      if (push_progress_[static_cast<size_t>(*it)].push >= 0) continue;
      const Motion& node = motions_[static_cast<size_t>(*it)];
      physics::Simulation simulation(world_);
      simulation.restore(node.state);
      const std::optional<std::vector<int>> cells = lattice.arrangement(simulation.environment());
      const int robot = lattice.robot_cell(node.robot);
      if (!cells || robot < 0) continue;
      ++lookahead_replans_;
      const lookahead::PushSearch search =
          lookahead::PushSearcher(lattice, stages_, task_.labelling).search(node.stage, *cells, robot, {}, {kReplanArrangements});
      if (!search.found) return;
      order_steps_ = search.steps;
      push_lead_.emplace(lattice, *cells, order_steps_, knowledge_);
      best_push_remaining_ = std::numeric_limits<double>::infinity();
      furthest_push_ = -1;
      ranked_on_order_.clear();
      for (size_t m = 0; m < motions_.size(); ++m) {
        push_progress_[m] = push_lead_->progress(motions_[m].state, -1);
        furthest_push_ = std::max(furthest_push_, push_progress_[m].push);
        best_push_remaining_ = std::min(best_push_remaining_, push_progress_[m].remaining);
        if (!dropped_[m]) rank_on_order(static_cast<int>(m));
      }
      return;
    }
  }

  // SampleControlAndSteps and propagation for the whole batch. The tree is only read meanwhile.
  // `alongside`, if given, runs as one more task of the batch, first.
  // add_growths() stops at the first expansion (in the order chosen) that reached acceptance, so those
  // after it that have not started are skipped: the plan, the tree and the statistics stay the same with
  // any number of threads, and one thread grows no expansion of the solving batch past the first that
  // accepts. A skipped expansion's growth is emptied, so that nothing stale is left to read.
  void grow_in_parallel(const std::function<void()>& alongside) {
    growths_.resize(expansions_.size());
    const int extra = alongside ? 1 : 0;
    std::atomic<int> first_accepted{std::numeric_limits<int>::max()};
    pool_.run(static_cast<int>(expansions_.size()) + extra, [&](int worker, int task) {
      if (task < extra) return alongside();
      const int expansion = task - extra;
      if (expansion > first_accepted.load(std::memory_order_relaxed)) {
        growths_[static_cast<size_t>(expansion)] = Growth{};
        return;
      }
      // Built on the thread that uses it: ODE keeps per-thread data.
      auto& grower = growers_[static_cast<size_t>(worker)];
      if (!grower) {
        grower.emplace(world_, task_, stages_, knowledge_, decomposition_, graph_, object_lead_,
                       knowledge_mode_);
      }
      const Expansion& e = expansions_[static_cast<size_t>(expansion)];
      Growth& growth = growths_[static_cast<size_t>(expansion)];
      const Motion& from = motions_[static_cast<size_t>(e.from)];
      if (e.guidance == Guidance::kFollowingOrder) {
        grower->follow_order(from, *push_lead_, e.push, growth);
      } else {
        grower->grow(from, e.target, e.goal ? &*e.goal : nullptr, e.guidance, e.seed, growth);
      }
      if (!growth.accepted) return;
      int seen = first_accepted.load(std::memory_order_relaxed);
      while (expansion < seen && !first_accepted.compare_exchange_weak(seen, expansion)) {
      }
    });
  }

  // Adds the batch's motions in the order the expansions were chosen. Returns the first motion that
  // reached acceptance, or -1.
  int add_growths() {
    for (size_t i = 0; i < growths_.size(); ++i) {
      Growth& growth = growths_[i];
      stats_.propagations += growth.controls;
      if (expansions_[i].guidance == Guidance::kFollowingOrder) primitive_controls_ += growth.controls;
      stats_.physics_steps += growth.physics_steps;
      stats_.invalid_steps += growth.stopped_by_invalid_step ? 1 : 0;
      if (growth.refusal) stats_.refused.add(*growth.refusal);
      if (growth.route_choice_cut) stats_.refused.add_own(own_rule(OwnRefusal::kRouteChoiceCut));
      note_outcome(expansions_[i].from, growth);
      int parent = expansions_[i].from;
      for (Motion& motion : growth.motions) {
        motion.parent = parent;
        parent = static_cast<int>(motions_.size());
        add_motion(std::move(motion));
        // The primitive from any motion of its chain would grow the same chain again.
        if (expansions_[i].guidance == Guidance::kFollowingOrder) primitive_tried_[static_cast<size_t>(parent)] = true;
      }
      if (growth.accepted) return parent;
    }
    return -1;
  }

  void note_outcome(int from, const Growth& growth) {
    int& failures = failed_starts_[static_cast<size_t>(from)];
    if (!growth.motions.empty() || !growth.stopped_by_invalid_step) {
      failures = 0;
      return;
    }
    // The root stays: a robot at rest can always move.
    if (++failures == kFailuresBeforeDropped && from != 0 && !dropped_[static_cast<size_t>(from)]) drop(from);
  }

  // No expansion grows from node `m` any more, neither along the lead nor for a body move. A stage where a
  // body must move can lose every node so (the robot pressed against a body whose side INFERENCE has just
  // switched off: each first step touches it from a forbidden side), and so can the node the lead starts
  // from; the lead then starts from the next node of that node's stage, or, with none left, the frontier
  // goes back to the nearest stage to acceptance that still has a node, the lead starting from its first.
  void drop(int m) {
    const Motion& motion = motions_[static_cast<size_t>(m)];
    stats_.refused.add_own(own_rule(OwnRefusal::kDroppedNode));
    ++stage_dropped_[static_cast<size_t>(motion.stage)];
    dropped_[static_cast<size_t>(m)] = true;
    if (push_lead_) ranked_on_order_.erase({order_rank(m), m});
    graph_.remove_motion(motion.product_state, m);
    std::vector<int>& nodes = stage_motions_[static_cast<size_t>(motion.stage)];
    nodes.erase(std::find(nodes.begin(), nodes.end(), m));
    const bool stranded = nodes.empty() && motion.stage == frontier_stage_ && stages_.body_move(frontier_stage_);
    if (m != segment_start_ && !stranded) return;
    if (!nodes.empty()) {
      segment_start_ = nodes.front();
      return;
    }
    // The nearest stage, and of equally near ones the one reached first. The root's always has a node.
    int nearest = -1;
    for (int s = 0; s < stages_.stages(); ++s) {
      const int distance = stages_.distance(s);
      const auto& held = stage_motions_[static_cast<size_t>(s)];
      if (held.empty() || distance < 0) continue;
      if (nearest < 0 || distance < closest_to_accept_ ||
          (distance == closest_to_accept_ && held.front() < stage_motions_[static_cast<size_t>(nearest)].front())) {
        nearest = s;
        closest_to_accept_ = distance;
      }
    }
    frontier_stage_ = nearest;
    segment_start_ = stage_motions_[static_cast<size_t>(nearest)].front();
  }

  void finish(planning::PlanResult& result, int solution, std::chrono::steady_clock::time_point started, planning::StopReason reason) {
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
      result.tree.push_back({motions_[motions_[m].parent].robot, motions_[m].robot, stages_.automaton_state_of(motions_[m].stage)});
    }
    stats_.tree_nodes = static_cast<long long>(motions_.size());
    stats_.planning_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    result.stats = stats_;
    auto report = std::make_shared<SearchReport>();
    if (lookahead_ != nullptr) report->lookahead = lookahead_->plan;
    report->lookahead_replans = lookahead_replans_;
    report->primitive_controls = primitive_controls_;
    if (!result.solved) report->end = search_end();
    result.own = std::move(report);
  }

  SearchEnd::Stage describe(int stage) const {
    return {stages_.automaton_state_of(stage), task_.labelling.object_facts(stages_.facts_of(stage)), stages_.distance(stage)};
  }

  SearchEnd search_end() const {
    SearchEnd end;
    end.frontier = describe(frontier_stage_);
    if (const auto& move = stages_.body_move(frontier_stage_)) {
      const physltl::knowledge::Labelling::NamedPart& part = task_.labelling.named_parts()[static_cast<size_t>(move->named)];
      const std::string& name = part.name;
      const auto region = [&](int place) { return part.set_names[static_cast<size_t>(place - 1)]; };
      if (move->place > 0) {
        end.body_move = name + " to " + region(move->place);
      } else {
        const int from = task_.labelling.place(stages_.facts_of(frontier_stage_), move->named);
        end.body_move = name + " out of " + (from > 0 ? region(from) : std::string("its regions"));
      }
    } else if (current_lead_ != nullptr) {
      for (int product : *current_lead_) {
        end.lead.push_back({decomposition_.triangles()[static_cast<size_t>(graph_.triangle_of(product))].centroid,
                            stages_.automaton_state_of(graph_.stage_of(product))});
      }
    }
    for (int stage : stages_reached_) {
      end.nodes_per_stage.push_back({describe(stage), stage_nodes_[static_cast<size_t>(stage)], stage_dropped_[static_cast<size_t>(stage)]});
    }
    if (push_lead_ && furthest_push_ >= 0 && furthest_push_ < push_lead_->pushes()) {
      end.order_push = furthest_push_ + 1;
      end.order_pushes = push_lead_->pushes();
      end.unfinished_push = lookahead::runs_of(*lookahead_->lattice, order_steps_)[static_cast<size_t>(furthest_push_)];
    }
    end.expansions_since_progress = expansions_since_progress_;
    end.widened = widened_;
    return end;
  }

  const scenario::World& world_;
  const planning::TaskAutomaton& task_;
  const physltl::knowledge::AbstractKnowledge& knowledge_;
  const decomposition::Decomposition& decomposition_;
  const planning::PlannerOptions& options_;
  const bool knowledge_mode_;  // the knowledge planner; otherwise the baseline
  const bool primitives_;      // the look-ahead's order carried out by push primitives (--push-primitives)
  std::shared_ptr<const planning::StageGraph> stage_graph_;  // the preparation's, or the search's own
  const planning::StageGraph& stages_;
  const RouteChoice routes_;
  ProductGraph graph_;
  LeadSearch lead_search_;
  ObjectLead object_lead_;
  planning::Random random_;
  std::vector<Motion> motions_;
  int closest_to_accept_ = 0;             // fewest stage moves to acceptance from any node not dropped
  int frontier_stage_ = 0;                // the stage of the first node that got that close
  int segment_start_ = 0;                 // where the lead starts: the root, or the frontier stage's first node
  std::vector<int> failed_starts_;        // per motion: expansions in a row that failed at once
  std::vector<int> chosen_;               // per motion: times it was chosen to grow from
  std::vector<bool> dropped_;             // per motion: no longer chosen but by a widened expansion
  std::vector<bool> primitive_tried_;     // per motion: the push primitive has grown from it
  long long expansions_since_progress_ = 0;
  // The fewest lead states after the furthest node of the frontier's stage, over the leads of that stage.
  int fewest_lead_states_left_ = std::numeric_limits<int>::max();
  bool widened_ = false;                  // the search has stalled at least once
  const std::vector<int>* current_lead_ = nullptr;
  const lookahead::Lookahead* lookahead_ = nullptr;   // the look-ahead the search follows, if any
  int lookahead_replans_ = 0;                          // times its order was planned again
  std::vector<lookahead::PushStep> order_steps_;       // its order as it stands
  std::optional<PushPlanLead> push_lead_;             // and as the tree follows it
  int furthest_push_ = -1;                             // the furthest push of it any node stands at
  long long primitive_controls_ = 0;                   // controls the push primitives propagated
  std::vector<PushPlanLead::Progress> push_progress_;  // per motion, where it stands on that order
  std::set<std::pair<double, int>> ranked_on_order_;  // the nodes on it, not dropped, by order_rank
  double best_push_remaining_ = std::numeric_limits<double>::infinity();
  long long batches_since_push_progress_ = 0;      // batches of look-ahead expansions without a node further along
  std::vector<int> available_;         // indices into the current lead
  std::vector<double> cumulative_;     // running sums of their weights
  double frontier_weight_ = 0.0;       // the running sum where the frontier starts
  std::vector<Expansion> expansions_;  // the current batch
  std::vector<Growth> growths_;        // what each of them grew
  planning::PlannerStats stats_;
  WorkerPool pool_;
  std::vector<std::optional<TreeGrower>> growers_;  // one per worker
  std::vector<std::vector<int>> stage_motions_;     // per stage, its nodes that are not dropped
  std::vector<long long> stage_nodes_;              // per stage, every node grown into it
  std::vector<long long> stage_dropped_;            // per stage, the nodes dropped
  std::vector<int> stages_reached_;                 // the stages holding a node, in the order reached
};

}  // namespace

const planning::PlannerParameter& push_primitives_parameter() {
  static const planning::PlannerParameter parameter{
      "push-primitives",
      "Whether the look-ahead's push order is first carried out by closed-loop push primitives (on) or by sampled controls alone (off)",
      {"on", "off"},
      [](const std::string& value) {
        return value == "off" ? "the knowledge planner follows its push order with sampled controls alone (--push-primitives off)" : "";
      }};
  return parameter;
}

planning::PlanResult plan_with_tree_search(const planning::Problem& problem, const KnowledgePreparation* prepared, const planning::PlannerOptions& options,
                                 TreeSearchMode mode) {
  const auto started = std::chrono::steady_clock::now();
  return Search(problem, prepared, options, mode).run(started);
}

}  // namespace physltl::planners::knowledge
