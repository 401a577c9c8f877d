#include "product_graph.h"

#include <algorithm>
#include <limits>
#include <functional>

namespace physltl::planners::knowledge {

ProductGraph::ProductGraph(const decomposition::Decomposition& decomposition, const planning::StageGraph& stages,
                           std::vector<float> lead_factor)
    : stages_(stages), stages_count_(stages.stages()), lead_factor_(std::move(lead_factor)) {
  for (const auto& triangle : decomposition.triangles()) {
    first_neighbour_.push_back(static_cast<int>(neighbours_.size()));
    for (int t : triangle.neighbors) neighbours_.push_back({t, decomposition.triangles()[t].region});
    areas_.push_back(triangle.area);
  }
  first_neighbour_.push_back(static_cast<int>(neighbours_.size()));
  lead_search_.resize(static_cast<size_t>(decomposition.size()) * static_cast<size_t>(stages_count_));
}

double ProductGraph::volume_per_distance(int id) const {
  // Zero for states from which acceptance is out of reach: the lead never enters them.
  const int distance = stages_.distance(stage_of(id));
  return distance < 0 ? 0.0 : areas_[static_cast<size_t>(triangle_of(id))] / (distance + 1.0);
}

double ProductGraph::weight(int id, int motions, int selections) const {
  const double selected = static_cast<double>(selections) + 1.0;
  return (static_cast<double>(motions) + 1.0) * volume_per_distance(id) / (selected * selected);
}

double ProductGraph::weight(int id) const {
  const auto motions = motions_.find(id);
  const auto selections = selections_.find(id);
  return weight(id, motions == motions_.end() ? 0 : static_cast<int>(motions->second.size()),
                selections == selections_.end() ? 0 : selections->second);
}

const std::vector<int>& ProductGraph::motions(int id) const {
  static const std::vector<int> kNone;
  const auto found = motions_.find(id);
  return found == motions_.end() ? kNone : found->second;
}

double ProductGraph::entry_cost(int id) const {
  const auto changed = entry_cost_.find(id);
  if (changed != entry_cost_.end()) return changed->second;
  return (lead_factor_.empty() ? 1.0 : lead_factor_[static_cast<size_t>(id)]) / weight(id, 0, 0);
}

void ProductGraph::update_entry_cost(int id) {
  entry_cost_[id] = (lead_factor_.empty() ? 1.0 : lead_factor_[static_cast<size_t>(id)]) / weight(id);
}

void ProductGraph::add_motion(int id, int motion) {
  motions_[id].push_back(motion);
  update_entry_cost(id);
}

void ProductGraph::remove_motion(int id, int motion) {
  std::erase(motions_[id], motion);
  update_entry_cost(id);
}

void ProductGraph::count_selection(int id) {
  ++selections_[id];
  update_entry_cost(id);
}

std::vector<int> ProductGraph::lead(int start, int horizon) {
  // The search's buffers stay between searches because the planner asks for a lead dozens of times a
  // second, and a new search forgets the last in O(1) (geometry/shortest_paths.h): resetting every state
  // of a large product would cost more than searching the part of it the lead needs.
  lead_search_.start();
  lead_search_.seed(start, 0.0);
  const int goal = lead_search_.run([&](int u, double c) {
    const int stage = stage_of(u);
    const int distance = stages_.distance(stage);
    if (distance >= 0 && (distance <= horizon || stages_.body_move(stage))) return false;
    const int triangle = triangle_of(u);
    for (int n = first_neighbour_[triangle]; n < first_neighbour_[triangle + 1]; ++n) {
      const int next = stages_.after_robot(stage, neighbours_[n].region);
      if (stages_.distance(next) < 0) continue;
      const int v = id(neighbours_[n].triangle, next);
      lead_search_.relax(u, v, c + entry_cost(v));
    }
    return true;
  });
  return goal < 0 ? std::vector<int>{} : lead_search_.path_to(goal);
}

}  // namespace physltl::planners::knowledge
