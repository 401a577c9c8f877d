#pragma once
// The high level of the planner: states (triangle, stage), their exploration statistics, and the lead:
// the cheapest product path from a start to acceptance, or to a stage where a body must move first,
// under the current weights. A stage is an automaton state with the places of the bodies the task names
// (stage_graph.h); for a task about the robot alone, the automaton state.

#include "physltl/decomposition/decomposition.h"
#include "physltl/geometry/shortest_paths.h"
#include "physltl/planning/stage_graph.h"

#include <unordered_map>
#include <utility>
#include <vector>

namespace physltl::planners::knowledge {

class ProductGraph {
 public:
  // `lead_factor`, when given, makes each product state that much dearer in the lead search only (1: as
  // Bhatia et al.): the knowledge planner's lead goes round the bodies where the task needs no push
  // (route_choice.h). Where to grow keeps the plain weights.
  ProductGraph(const decomposition::Decomposition& decomposition, const planning::StageGraph& stages,
               std::vector<float> lead_factor = {});

  int id(int triangle, int stage) const { return triangle * stages_count_ + stage; }
  int triangle_of(int id) const { return id / stages_count_; }
  int stage_of(int id) const { return id % stages_count_; }

  // Book-keeping the weights depend on (Bhatia et al. 2010, as in OMPL's LTLPlanner).
  void add_motion(int id, int motion);
  void remove_motion(int id, int motion);
  void count_selection(int id);
  const std::vector<int>& motions(int id) const;
  double weight(int id) const;

  // Product states from `start` to the first one whose stage is at most `horizon` moves from acceptance
  // (0: an accepting one) or needs a body moved first, cheapest under 1/weight; empty if none.
  std::vector<int> lead(int start, int horizon = 0);
  // Product states settled by every lead search so far: their cost, which grows with the world.
  long long lead_work() const { return lead_search_.settled(); }

 private:
  const planning::StageGraph& stages_;
  int stages_count_;
  // The lead search's view of the decomposition, flat: for each triangle its neighbours and their regions.
  struct Neighbour {
    int triangle;
    int region;
  };
  std::vector<int> first_neighbour_;  // per triangle, into neighbours_; one more entry at the end
  std::vector<Neighbour> neighbours_;
  // The product can hold a hundred million states (a thousand triangles, 2^16 places of the named
  // bodies); a search meets a few thousand. So what a state holds is kept only for the states met, and
  // the rest is computed from the triangle and the stage.
  std::vector<double> areas_;  // per triangle
  // The weight's constant part: triangle area over (the stage's moves to acceptance + 1).
  double volume_per_distance(int id) const;
  double weight(int id, int motions, int selections) const;
  double entry_cost(int id) const;  // 1 / (weight * lead scale): the lead search reads it for every edge
  void update_entry_cost(int id);
  std::unordered_map<int, std::vector<int>> motions_;
  std::unordered_map<int, int> selections_;
  std::unordered_map<int, double> entry_cost_;  // of the states whose motions or selections changed
  std::vector<float> lead_factor_;  // per product state; empty: all 1
  geometry::ShortestPaths lead_search_;
};

}  // namespace physltl::planners::knowledge
