#include "physltl/geometry/shortest_paths.h"

#include <new>

namespace physltl::geometry {
namespace {

template <class T>
T* zeroed(std::size_t count) {
  void* p = std::calloc(std::max<std::size_t>(count, 1), sizeof(T));
  if (p == nullptr) throw std::bad_alloc();
  return static_cast<T*>(p);
}

}  // namespace

void ShortestPaths::resize(std::size_t nodes) {
  nodes_ = nodes;
  distance_.reset(zeroed<double>(nodes));
  previous_.reset(zeroed<int>(nodes));
  stamp_.reset(zeroed<unsigned>(nodes));
  search_ = 1;
  open_.clear();
}

void ShortestPaths::start() {
  open_.clear();
  if (++search_ == 0) {
    // The stamps wrapped round: forget them all once.
    std::fill(stamp_.get(), stamp_.get() + nodes_, 0u);
    search_ = 1;
  }
}

void ShortestPaths::reach(int node, int from, double distance) {
  const auto at = static_cast<std::size_t>(node);
  stamp_[at] = search_;
  distance_[at] = distance;
  previous_[at] = from;
  open_.push_back({distance, node});
  std::push_heap(open_.begin(), open_.end(), std::greater<>{});
}

std::vector<double> ShortestPaths::distances() const {
  std::vector<double> all(nodes_, kUnreached);
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (stamp_[i] == search_) all[i] = distance_[i];
  }
  return all;
}

std::vector<int> ShortestPaths::path_to(int node) const {
  std::vector<int> path;
  for (int v = node; v >= 0; v = previous(v)) path.push_back(v);
  std::reverse(path.begin(), path.end());
  return path;
}

}  // namespace physltl::geometry
