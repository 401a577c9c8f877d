#pragma once
// The high level of the planner: states (triangle, automaton state), their exploration statistics, and
// the lead: the cheapest product path from the start to acceptance under the current weights.

#include "physltl/decomposition/decomposition.h"
#include "physltl/planning/task.h"

#include <span>
#include <utility>
#include <vector>

namespace physltl::planning {

class ProductGraph {
 public:
  // `triangle_weight`, when given, scales each triangle's weight in the lead search only (1: as Bhatia et
  // al.; less: the lead avoids it); where to grow keeps the plain weights.
  ProductGraph(const decomposition::Decomposition& decomposition, const TaskAutomaton& task,
               std::span<const double> triangle_weight = {});

  int id(int triangle, int automaton_state) const { return triangle * automaton_states_ + automaton_state; }
  int triangle_of(int id) const { return id / automaton_states_; }
  int automaton_state_of(int id) const { return id % automaton_states_; }
  bool accepting(int id) const { return task_.dfa.accepting[automaton_state_of(id)]; }
  // No accepting state can follow: trees never grow there.
  bool dead(int automaton_state) const { return distance_to_accept_[automaton_state] < 0; }

  // Book-keeping the weights depend on (Bhatia et al. 2010, as in OMPL's LTLPlanner).
  void add_motion(int id, int motion);
  void remove_motion(int id, int motion);
  void count_selection(int id);
  const std::vector<int>& motions(int id) const { return motions_[id]; }
  double weight(int id) const {
    const double selected = static_cast<double>(selections_[id]) + 1.0;
    return (static_cast<double>(motions_[id].size()) + 1.0) * volume_per_distance_[id] / (selected * selected);
  }

  // Automaton steps from the state to acceptance, over letters with at most one region; -1 never.
  int distance_to_accept(int automaton_state) const { return distance_to_accept_[automaton_state]; }

  // Product states from `start` to the first one whose automaton state is at most `horizon` steps from
  // acceptance (0: an accepting one), cheapest under 1/weight; empty if none.
  std::vector<int> lead(int start, int horizon = 0);
  // Product states settled by every lead search so far: their cost, which grows with the world.
  long long lead_work() const { return lead_work_; }

 private:
  const TaskAutomaton& task_;
  int automaton_states_;
  std::vector<int> distance_to_accept_;  // automaton steps, over letters with at most one region; -1 never
  // The lead search's view of the decomposition, flat: for each triangle its neighbours and their regions.
  struct Neighbour {
    int triangle;
    int region;
  };
  std::vector<int> first_neighbour_;  // per triangle, into neighbours_; one more entry at the end
  std::vector<Neighbour> neighbours_;
  // The weight's constant part: triangle area over (automaton steps to acceptance + 1).
  std::vector<double> volume_per_distance_;
  std::vector<std::vector<int>> motions_;
  std::vector<int> selections_;
  void update_entry_cost(int id);
  std::vector<double> lead_scale_;  // per triangle
  std::vector<double> entry_cost_;  // 1 / (weight * lead scale), kept up to date: the lead search reads it for every edge
  std::vector<double> lead_cost_;
  std::vector<int> lead_previous_;
  std::vector<unsigned> lead_stamps_;  // per state: the search that last set its cost
  unsigned lead_stamp_ = 0;
  long long lead_work_ = 0;
  std::vector<std::pair<double, int>> lead_open_;
};

}  // namespace physltl::planning
