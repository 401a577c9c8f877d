#pragma once
// The look-ahead's discrete search: over arrangements of the lattice's bodies (push_lattice.h) and the
// task's stage, by pushes of one body one step (the robot walks, between pushes, through the places no
// body holds), until the stage needs no more body moves; a line of bodies pushed end to end may end it.
// Weighted A*: a push costs the bodies it moves, and the estimate is the fewest pushes, each named body
// alone, to the places of one fact set that ends the pushing; the bodies of a group the fact set wants in
// a region set (Sokoban's any box on any goal) are matched to its places at least cost, so two boxes
// never count one goal; with more such fact sets than kMaxEndings, each body's fewest pushes to any of
// its places. Pruned inside this search only: arrangements where the automaton dies, a body the task needs
// somewhere on a place it can never be pushed there from (a box against a wall its goal is not along),
// four places in a square all held by walls or bodies, no two bodies side by side, one of them a body
// not yet where the task needs it (none of them can move again), and more generally a body pushed where
// it can be pushed along neither axis again, held so by walls, dead places or bodies that are themselves
// held so (frozen), with one of those bodies not where the task needs it; and places the robot cannot walk
// to, closed off by bodies that cannot all get where the task needs them without it (a corral deadlock).
// Macros: a box in a tunnel is pushed on through it (in_tunnel), and a box pushed into a goal room also
// on to the room's deepest free goal (goal_room.h). The arrangements met are kept compactly
// (arrangement_store.h), within a budget of arrangements and of memory.

#include "push_lattice.h"
#include "physltl/base/deadline.h"
#include "physltl/geometry/assignment.h"
#include "physltl/planning/stage_graph.h"

#include <cstddef>
#include <set>
#include <string>
#include <vector>

namespace physltl::planners::knowledge::lookahead {

// Measured on the look-ahead puzzles (docs/benchmarks.md): 2 finds orders for the hardest in seconds
// with pushes within a few of the fewest; 1 (plain A*) settled ten times as many arrangements.
inline constexpr double kHeuristicWeight = 2.0;
// A run's budget grows with its time limit (run_arrangements), up to kMaxArrangements, well under the
// memory cap below (an arrangement met costs some 40 bytes, one settled 8 more and 4 a body).
inline constexpr long long kMaxArrangements = 4'000'000;
inline constexpr long long kArrangementsPerSecond = 50'000;
// The most memory one search may hold (arrangement_store.h); past it, the search ends ("memory limit").
inline constexpr std::size_t kMaxSearchBytes = std::size_t{2} << 30;
// `check`'s budget (a preview, planner_entry.h): about a second on the slowest level of the collections
// measured (docs/planner.md), the same answer on any machine.
inline constexpr long long kPreviewArrangements = 20'000;
// The estimate weighs each arrangement against every ending fact set up to this many (a Sokoban level of
// 6 boxes, any box on any goal, has 720); beyond it, the bodies' places are taken apart.
inline constexpr int kMaxEndings = 1024;
// A group of up to this many bodies is matched to its places exactly (O(n^3) per arrangement); a larger
// one by the larger of two sums, each body's cheapest place and, as many places as bodies, each place's
// cheapest body: both lower bounds on any matching.
inline constexpr int kMaxMatchedBodies = 20;

// The arrangements a run with a time limit of `time_limit_s` may settle: kArrangementsPerSecond for each
// second, from kPreviewArrangements to kMaxArrangements (all of it without a limit). A search that takes
// the whole limit leaves the physics nothing: Microban II 130 needs 5 pushes that the look-ahead does not
// find in 4 million arrangements, and the physics search finds them in a second. Measured, the look-ahead
// settles 60,000 to 300,000 a second, so it keeps half a minute's run for the physics at the least; and a
// function of the limit the user gave, not of the clock, it searches alike on any machine.
long long run_arrangements(double time_limit_s);

// What one search may spend: the arrangements it settles and the memory it holds, both counted from
// what it did (not from the clock or the machine), so that a search ends the same way everywhere.
struct SearchBudget {
  long long arrangements = kMaxArrangements;
  std::size_t bytes = kMaxSearchBytes;
};

struct PushStep {
  int body = 0;  // lattice body: the one the robot pushes
  int direction = 0;
  int from = 0, to = 0;  // its places
  // Lattice bodies in a line ahead of it, nearest first, that it pushes along end to end: physics moves
  // boxes so where the drive overcomes their friction together (a row in a corridor). Only the last
  // pushes of an order move lines.
  std::vector<int> ahead;
};

// Whether `next` goes on with `step`'s push: the same body, way and line ahead (one push of the order).
inline bool same_run(const PushStep& step, const PushStep& next) {
  return step.body == next.body && step.direction == next.direction && step.ahead == next.ahead;
}

struct PushSearch {
  bool found = false;
  std::vector<PushStep> steps;
  long long settled = 0;
  std::string outcome;  // "found", "no order of pushes", "search limit", "memory limit"
};

class PushSearcher {
 public:
  PushSearcher(const PushLattice& lattice, const planning::StageGraph& stages, const physltl::knowledge::Labelling& labelling);

  // From `stage` with the lattice bodies on `cells` and the robot on `robot_cell`, within `budget` (the
  // same order on any machine); `deadline` only ends it early (DeadlineReached). `weight` scales the
  // estimate against the cost so far: 0 is a uniform-cost search, whose order has the fewest body steps
  // (for tests of the estimate).
  PushSearch search(int stage, const std::vector<int>& cells, int robot_cell, const base::Deadline& deadline = {},
                    SearchBudget budget = {}, double weight = kHeuristicWeight) const;
  // The estimate the search ranks arrangements by: never more than the body steps left from `cells`.
  int estimate(int stage, const std::vector<int>& cells) const;
  // Whether body k on `cell` can still get to where the task needs it, pushed alone; always true for a
  // body the task leaves free.
  bool alive(int stage, int k, int cell) const;
  // Whether body k on cells[k] can be pushed along neither axis again, nor can a body that holds it so,
  // and one of them is not where the task wants it from `stage` (FreezeTest in push_search.cpp).
  bool frozen_apart(int stage, const std::vector<int>& cells, int k) const;
  // Whether places the robot on `robot_cell` cannot walk to make a corral whose bodies, alone on the
  // lattice, can neither all get where the task wants them nor let the robot in (CorralTest in
  // push_search.cpp).
  bool corralled(int stage, const std::vector<int>& cells, int robot_cell) const;

 private:
  friend class ArrangementSearch;
  friend class FreezeTest;
  friend class CorralTest;
  // Per lattice body, per place: the fewest pushes of that body alone to where the task wants it from a
  // stage (kNever where it can get there no more); no table for a body the task leaves free.
  struct Goals {
    std::vector<std::vector<int>> pushes_left;
    // The ending fact sets, each as the place (labelling.h) of every lattice body (0 for one the task
    // leaves free), and per lattice body, per place, per cell: the fewest pushes of it alone to that place
    // (empty when the endings are too many to weigh).
    std::vector<std::vector<int>> endings;
    std::vector<std::vector<std::vector<int>>> pushes_to_place;
    // Per group whose bodies an ending wants in one of its region sets (`place`): its lattice bodies, the
    // places of the set they fit on, and per body, per cell, per such place, the fewest pushes of the body
    // alone there (pushes[i][cell * targets.size() + j]: a body's row of the cost matrix in one piece).
    struct Matching {
      int part = 0, place = 0;
      std::vector<int> bodies, targets;
      std::vector<std::vector<int>> pushes;
      int cost(const std::vector<int>& cells, std::vector<int>& scratch, geometry::Assignment& assignment) const;
    };
    std::vector<Matching> matchings;
    std::vector<bool> matched;  // per lattice body: in a group of several, weighed by the group's matching
    int left(int k, int cell) const;           // 0 for a body the task leaves free
    // A lower bound on the body steps left: the cheapest ending, each body pushed alone, a group's bodies
    // matched to distinct places.
    int estimate(const std::vector<int>& cells) const;

   private:
    mutable std::vector<int> scratch_;  // the cost matrix of a matching: a Goals belongs to one search
    mutable geometry::Assignment assignment_;
  };
  // Per place, the fewest pushes of lattice body k alone to one of `targets`.
  std::vector<int> pushes_to_cells(int k, const std::vector<int>& targets) const;
  // A group's tables: each body's pushes to each target place, a walk of the lattice per pair (a group
  // of 250 boxes makes 62,500 of them), so it checks `deadline` (DeadlineReached).
  void add_matchings(Goals& goals, const base::Deadline& deadline) const;
  // Per place, the fewest pushes of lattice body k alone to a place whose labelling place is in `places`.
  std::vector<int> pushes_to(int k, const std::set<int>& places) const;
  Goals goals_from(int stage, const base::Deadline& deadline = {}) const;
  // The stage needs no more body moves: the robot's part of the task, or acceptance.
  bool ends_pushing(int stage) const;
  int facts_of(int stage, const std::vector<int>& cells) const;
  int stage_after(int stage, const std::vector<int>& cells) const;
  // Four places in a square holding `at`, all walls or bodies, no two bodies side by side (a line of
  // them may still move), one a body not where the task wants it.
  bool square_frozen(const Goals& goals, const std::vector<int>& cells, const std::vector<int>& holder, int at) const;

  const PushLattice& lattice_;
  const planning::StageGraph& stages_;
  const physltl::knowledge::Labelling& labelling_;
};

}  // namespace physltl::planners::knowledge::lookahead
