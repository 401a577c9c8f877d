#pragma once
// Dijkstra's shortest paths over a graph whose nodes are numbered 0..n-1 and whose edges the caller
// offers as each node is settled: the one routine behind the reachability fields, the route choice, the
// object lead, the path bounds and the knowledge planner's lead (the free space's distances among
// obstacles are a search over areas, not a graph: free_space_search.h). Nodes are settled nearest first and, at equal distances, lowest number first, so a search is
// the same on every machine. The search's state stays between searches, and a new search forgets the
// last in O(1) (a node counts as reached only if this search reached it): a search that touches a few
// nodes of a large graph costs what it touches.

#include <algorithm>
#include <cstddef>
#include <functional>
#include <cstdlib>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace physltl::geometry {

class ShortestPaths {
 public:
  static constexpr double kUnreached = std::numeric_limits<double>::infinity();

  explicit ShortestPaths(std::size_t nodes = 0) { resize(nodes); }
  void resize(std::size_t nodes);
  std::size_t size() const { return nodes_; }

  // A new search: every node unreached.
  void start();
  // `node` reached at `distance`, with no predecessor.
  void seed(int node, double distance) { reach(node, -1, distance); }
  // `to` offered at `distance` by way of `from`: taken when `to` is unreached, or when it is nearer so.
  void relax(int from, int to, double distance) {
    if (!reached(to) || distance < distance_[static_cast<std::size_t>(to)]) reach(to, from, distance);
  }

  // Settles the reached nodes nearest first, calling settle(node, distance) once for each at its final
  // distance: it offers the node's edges (relax) and returns false to end the search at that node.
  // Returns the node the search ended at, or -1 when it settled every node it reached.
  template <class Settle>
  int run(Settle&& settle) {
    while (!open_.empty()) {
      std::pop_heap(open_.begin(), open_.end(), std::greater<>{});
      const auto [distance, node] = open_.back();
      open_.pop_back();
      if (distance > distance_[static_cast<std::size_t>(node)]) continue;
      ++settled_;
      if (!settle(node, distance)) return node;
    }
    return -1;
  }

  bool reached(int node) const { return stamp_[static_cast<std::size_t>(node)] == search_; }
  double distance(int node) const { return reached(node) ? distance_[static_cast<std::size_t>(node)] : kUnreached; }
  int previous(int node) const { return reached(node) ? previous_[static_cast<std::size_t>(node)] : -1; }
  // Every node's distance, kUnreached where the search did not reach.
  std::vector<double> distances() const;
  // The nodes from a seed to `node` along the predecessors, in that order.
  std::vector<int> path_to(int node) const;
  // Nodes settled by every search so far: what the searches cost.
  long long settled() const { return settled_; }

 private:
  void reach(int node, int from, double distance);

  // Per node, allocated zeroed by calloc: the pages of a large graph's arrays cost nothing until a search
  // reaches a node on them (the knowledge planner's product of triangles and stages can hold a hundred
  // million nodes, of which a search reaches a few thousand). A node's distance and predecessor are read
  // only once its stamp says this search reached it.
  struct Free {
    void operator()(void* p) const { std::free(p); }
  };
  template <class T>
  using Zeroed = std::unique_ptr<T[], Free>;
  std::size_t nodes_ = 0;
  Zeroed<double> distance_;
  Zeroed<int> previous_;
  Zeroed<unsigned> stamp_;  // the search that last reached the node; 0: none
  unsigned search_ = 1;
  std::vector<std::pair<double, int>> open_;  // a min-heap
  long long settled_ = 0;
};

}  // namespace physltl::geometry
