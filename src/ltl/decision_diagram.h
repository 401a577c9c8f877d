#pragma once
// Private to the ltl module: reduced ordered decision diagrams with integer leaves (multi-terminal
// BDDs), the symbolic transition functions of the translation. Variables are tested in increasing
// index order and nodes are shared, so two functions are equal exactly when their nodes are.

#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

namespace physltl::ltl::detail {

class DecisionDiagram {
 public:
  using Node = std::uint32_t;
  static constexpr int kLeafVar = std::numeric_limits<int>::max();

  Node leaf(int value) { return intern(Entry{kLeafVar, static_cast<Node>(value), 0}); }
  Node branch(int var, Node low, Node high) {
    if (low == high) return low;  // the test is redundant
    return intern(Entry{var, low, high});
  }

  bool is_leaf(Node n) const { return nodes_[n].var == kLeafVar; }
  int value(Node n) const { return static_cast<int>(nodes_[n].low); }
  int var(Node n) const { return nodes_[n].var; }
  Node low(Node n) const { return nodes_[n].low; }
  Node high(Node n) const { return nodes_[n].high; }

  // The cofactors of `n` for variable `v`, which must not be below the top variable of `n`.
  Node low_for(Node n, int v) const { return var(n) == v ? low(n) : n; }
  Node high_for(Node n, int v) const { return var(n) == v ? high(n) : n; }

  // The distinct leaf values of `n`, in order of a depth-first walk (low before high).
  std::vector<int> leaf_values(Node n) const {
    std::vector<int> out;
    std::vector<Node> stack{n};
    // Visited marks stamped with a fresh epoch per call: no clearing, no hashing.
    mark_.resize(nodes_.size(), 0);
    const std::uint32_t epoch = ++epoch_;
    while (!stack.empty()) {
      Node m = stack.back();
      stack.pop_back();
      if (mark_[m] == epoch) continue;
      mark_[m] = epoch;
      if (is_leaf(m)) {
        out.push_back(value(m));
      } else {
        stack.push_back(high(m));
        stack.push_back(low(m));
      }
    }
    return out;
  }

 private:
  struct Entry {
    int var;
    Node low;
    Node high;
  };
  struct KeyHash {
    std::size_t operator()(std::uint64_t k) const { return k * 0x9E3779B97F4A7C15ULL >> 7; }
  };

  // One node per (var, low, high): a map per variable, keyed by the two children.
  Node intern(const Entry& e) {
    auto& by_children = unique_[static_cast<std::uint64_t>(static_cast<std::uint32_t>(e.var))];
    const std::uint64_t key = (static_cast<std::uint64_t>(e.low) << 32) | e.high;
    auto [it, inserted] = by_children.try_emplace(key, static_cast<Node>(nodes_.size()));
    if (inserted) nodes_.push_back(e);
    return it->second;
  }

  std::vector<Entry> nodes_;
  mutable std::vector<std::uint32_t> mark_;  // scratch space of leaf_values
  mutable std::uint32_t epoch_ = 0;
  std::unordered_map<std::uint64_t, std::unordered_map<std::uint64_t, Node, KeyHash>> unique_;
};

}  // namespace physltl::ltl::detail
