#include "exclusivity.h"

#include "physltl/ltl/object_atom.h"

#include <algorithm>
#include <deque>

namespace physltl::ltl {

Exclusivity::Exclusivity(std::span<const std::string> propositions) {
  std::vector<std::string> bodies;
  for (const std::string& p : propositions) {
    const std::optional<ObjectAtom> object = object_atom(p);
    if (!object) {
      group_.push_back(0);
      continue;
    }
    auto body = std::find(bodies.begin(), bodies.end(), object->body);
    if (body == bodies.end()) body = bodies.insert(body, object->body);
    group_.push_back(static_cast<int>(body - bodies.begin()) + 1);
  }
  groups_ = static_cast<int>(bodies.size()) + 1;
}

bool Exclusivity::satisfiable(const Cube& cube) const {
  std::vector<int> required(static_cast<std::size_t>(groups_), -1);  // per group, the proposition required
  for (const Literal& l : cube) {
    const bool contradicted = std::any_of(cube.begin(), cube.end(), [&](const Literal& other) {
      return other.proposition == l.proposition && other.positive != l.positive;
    });
    if (contradicted) return false;
    if (!l.positive) continue;
    int& in_group = required[static_cast<std::size_t>(group(l.proposition))];
    if (in_group >= 0 && in_group != l.proposition) return false;
    in_group = l.proposition;
  }
  return true;
}

std::vector<bool> Exclusivity::reachable(const Dfa& dfa, int state) const {
  std::vector<bool> seen(dfa.size(), false);
  std::deque<int> queue{state};
  seen[static_cast<std::size_t>(state)] = true;
  while (!queue.empty()) {
    const int s = queue.front();
    queue.pop_front();
    for (const Edge& e : dfa.edges[static_cast<std::size_t>(s)]) {
      if (seen[static_cast<std::size_t>(e.target)]) continue;
      const bool taken = std::any_of(e.condition.cubes.begin(), e.condition.cubes.end(),
                                     [&](const Cube& c) { return satisfiable(c); });
      if (taken) seen[static_cast<std::size_t>(e.target)] = true, queue.push_back(e.target);
    }
  }
  return seen;
}

std::optional<std::vector<std::vector<int>>> Exclusivity::letters(std::size_t limit) const {
  // Each group contributes none or one of its propositions: the letters are their product.
  std::vector<std::vector<int>> members(static_cast<std::size_t>(groups_));
  for (std::size_t p = 0; p < group_.size(); ++p) members[static_cast<std::size_t>(group_[p])].push_back(static_cast<int>(p));
  std::size_t count = 1;
  for (const auto& m : members) {
    count *= m.size() + 1;
    if (count > limit) return std::nullopt;
  }
  std::vector<std::vector<int>> letters{{}};
  for (const auto& m : members) {
    std::vector<std::vector<int>> extended;
    for (const auto& letter : letters) {
      extended.push_back(letter);
      for (int p : m) {
        extended.push_back(letter);
        extended.back().push_back(p);
      }
    }
    letters = std::move(extended);
  }
  for (auto& letter : letters) std::sort(letter.begin(), letter.end());
  return letters;
}

}  // namespace physltl::ltl
