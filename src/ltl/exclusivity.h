#pragma once
// Which letters can occur. Regions are disjoint, so the robot is in at most one region at a time, and so
// is each body: the propositions fall into groups of which at most one holds at a time, the robot's
// (atoms without '@') and one per body (its BODY@REGION atoms, object_atom.h). Any mix across groups can
// hold together: the robot in the dock while the crate is there too.

#include "physltl/ltl/dfa.h"

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace physltl::ltl {

class Exclusivity {
 public:
  explicit Exclusivity(std::span<const std::string> propositions);

  // 0: the robot's; 1, 2, ...: one per body, in the order the bodies first appear.
  int group(int proposition) const { return group_[static_cast<std::size_t>(proposition)]; }
  int groups() const { return groups_; }
  bool has_object_atoms() const { return groups_ > 1; }

  // Whether a letter that can occur satisfies the cube: no proposition both required and excluded, and at
  // most one required in each group.
  bool satisfiable(const Cube& cube) const;
  // The states reachable from `state` over letters that can occur (with `state` itself).
  std::vector<bool> reachable(const Dfa& dfa, int state) const;
  // Every letter that can occur, as the indices of its true propositions, if there are at most `limit`.
  std::optional<std::vector<std::vector<int>>> letters(std::size_t limit) const;

 private:
  std::vector<int> group_;
  int groups_ = 1;
};

}  // namespace physltl::ltl
