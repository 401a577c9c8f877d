#include "product_graph.h"

#include <algorithm>
#include <limits>
#include <functional>

namespace physltl::planning {

ProductGraph::ProductGraph(const decomposition::Decomposition& decomposition, const StageGraph& stages,
                           std::vector<float> lead_factor)
    : stages_(stages),
      stages_count_(stages.stages()),
      motions_(static_cast<size_t>(decomposition.size()) * stages_count_),
      selections_(motions_.size(), 0) {
  for (const auto& triangle : decomposition.triangles()) {
    first_neighbour_.push_back(static_cast<int>(neighbours_.size()));
    for (int t : triangle.neighbors) neighbours_.push_back({t, decomposition.triangles()[t].region});
  }
  first_neighbour_.push_back(static_cast<int>(neighbours_.size()));
  volume_per_distance_.resize(motions_.size());
  for (size_t id = 0; id < motions_.size(); ++id) {
    const int i = static_cast<int>(id);
    // Zero for states from which acceptance is out of reach: the lead never enters them.
    const int distance = stages_.distance(stage_of(i));
    volume_per_distance_[id] = distance < 0 ? 0.0 : decomposition.triangles()[triangle_of(i)].area / (distance + 1.0);
  }
  lead_factor_ = std::move(lead_factor);
  entry_cost_.resize(motions_.size());
  lead_cost_.resize(motions_.size());
  lead_previous_.resize(motions_.size());
  lead_stamps_.assign(motions_.size(), 0u);
  for (size_t id = 0; id < motions_.size(); ++id) update_entry_cost(static_cast<int>(id));
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
  // Dijkstra; the buffers are members because the planner asks for a lead dozens of times a second, and a
  // state's cost counts only if it was set in this search (its stamp): resetting every state of a large
  // product would cost more than searching the part of it the lead needs.
  if (++lead_stamp_ == 0) std::fill(lead_stamps_.begin(), lead_stamps_.end(), 0u), lead_stamp_ = 1;
  auto reached = [&](int v) { return lead_stamps_[static_cast<size_t>(v)] == lead_stamp_; };
  std::vector<double>& cost = lead_cost_;
  std::vector<int>& previous = lead_previous_;
  std::vector<std::pair<double, int>>& open = lead_open_;  // a min-heap
  open.clear();
  lead_stamps_[static_cast<size_t>(start)] = lead_stamp_;
  cost[start] = 0.0;
  previous[start] = -1;
  open.push_back({0.0, start});
  int goal = -1;
  while (!open.empty()) {
    std::pop_heap(open.begin(), open.end(), std::greater<>{});
    const auto [c, u] = open.back();
    open.pop_back();
    if (c > cost[u]) continue;
    ++lead_work_;
    const int stage = stage_of(u);
    const int distance = stages_.distance(stage);
    if (distance >= 0 && (distance <= horizon || stages_.body_move(stage))) {
      goal = u;
      break;
    }
    const int triangle = triangle_of(u);
    for (int n = first_neighbour_[triangle]; n < first_neighbour_[triangle + 1]; ++n) {
      const int next = stages_.after_robot(stage, neighbours_[n].region);
      if (stages_.distance(next) < 0) continue;
      const int v = id(neighbours_[n].triangle, next);
      const double next_cost = c + entry_cost_[v];
      if (!reached(v) || next_cost < cost[v]) {
        lead_stamps_[static_cast<size_t>(v)] = lead_stamp_;
        cost[v] = next_cost;
        previous[v] = u;
        open.push_back({next_cost, v});
        std::push_heap(open.begin(), open.end(), std::greater<>{});
      }
    }
  }
  std::vector<int> path;
  for (int v = goal; v >= 0; v = previous[v]) path.push_back(v);
  std::reverse(path.begin(), path.end());
  return path;
}

}  // namespace physltl::planning
