#pragma once
// A deterministic, complete automaton over the letters 2^AP, with edges labelled by Boolean conditions.
//
// States are 0..size()-1. The edges leaving a state have pairwise disjoint conditions that together
// cover every letter, so exactly one edge applies to any valuation of the propositions.

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace physltl::ltl {

struct Literal {
  int proposition;  // index into Dfa::propositions
  bool positive;    // false: the proposition must be false
  friend bool operator==(const Literal&, const Literal&) = default;
};

// A conjunction of literals; the empty cube is true.
using Cube = std::vector<Literal>;

// A disjunction of cubes; the empty condition is false.
struct Condition {
  std::vector<Cube> cubes;
  // `truth[i]` is the value of proposition i.
  bool holds(std::span<const bool> truth) const;
  friend bool operator==(const Condition&, const Condition&) = default;
};

struct Edge {
  int target;
  Condition condition;
};

// What an accepting state says about the finite trace that reached it (docs/ltl.md).
enum class Acceptance {
  kGoodPrefix,   // co-safe tasks: every infinite continuation of the trace satisfies the formula
  kStopAndStay,  // other tasks: the trace followed by its last letter forever satisfies the formula
};

struct Dfa {
  Acceptance acceptance = Acceptance::kGoodPrefix;
  std::vector<std::string> propositions;  // the alphabet's atomic propositions, by index
  int start = 0;
  std::vector<bool> accepting;            // per state
  std::vector<std::vector<Edge>> edges;   // per state

  std::size_t size() const { return accepting.size(); }
  std::size_t edge_count() const;
  int proposition_index(std::string_view name) const;  // -1 if not in the alphabet

  // The successor of `state` on the letter where exactly the propositions in `true_props` (indices)
  // hold; every other proposition is false.
  int step(int state, std::span<const int> true_props) const;
  // The same, by value of every proposition.
  int step_by_truth(int state, std::span<const bool> truth) const;
  // Whether the finite trace (one set of true propositions per step) ends in an accepting state.
  bool accepts(std::span<const std::vector<int>> trace) const;
};

}  // namespace physltl::ltl
