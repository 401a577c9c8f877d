#pragma once
// The lead of Algorithm 3, kept up to date at a fraction of the cost of searching it from the start every
// time. The lead runs through the stages the tree has done (stage_graph.h: the automaton states it has left
// behind) and then the frontier's. Only the frontier part changes much between two leads: the tree grows
// there. So most updates search again only from where the lead enters the frontier's stage (to the
// current horizon, which may have moved on) and keep the part before it; every few updates the whole lead
// is searched again, less often when that costs more than the updates in between.

#include "product_graph.h"

#include <vector>

namespace physltl::planners::knowledge {

class LeadSearch {
 public:
  explicit LeadSearch(ProductGraph& graph) : graph_(graph) {}

  // The lead from `start` until an automaton state at most `horizon` steps from acceptance, as
  // ProductGraph::lead; empty if there is none.
  std::vector<int> next(int start, int horizon);

 private:
  ProductGraph& graph_;
  // The last whole lead up to and including its first state in the frontier's stage.
  std::vector<int> prefix_;
  int horizon_ = -1;
  int updates_since_whole_ = 0;
  long long whole_work_ = 0;     // product states the last whole search settled
  long long frontier_work_ = 0;  // and the frontier searches since
};

}  // namespace physltl::planners::knowledge
