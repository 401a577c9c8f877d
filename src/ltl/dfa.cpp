#include "physltl/ltl/dfa.h"

#include <algorithm>
#include <memory>
#include <stdexcept>

namespace physltl::ltl {

bool Condition::holds(std::span<const bool> truth) const {
  return std::ranges::any_of(cubes, [&](const Cube& cube) {
    return std::ranges::all_of(cube, [&](const Literal& l) { return truth[l.proposition] == l.positive; });
  });
}

std::size_t Dfa::edge_count() const {
  std::size_t n = 0;
  for (const auto& out : edges) n += out.size();
  return n;
}

int Dfa::proposition_index(std::string_view name) const {
  auto it = std::ranges::find(propositions, name);
  return it == propositions.end() ? -1 : static_cast<int>(it - propositions.begin());
}

int Dfa::step_by_truth(int state, std::span<const bool> truth) const {
  if (truth.size() != propositions.size()) throw std::invalid_argument("one truth value per proposition expected");
  for (const Edge& e : edges.at(static_cast<std::size_t>(state)))
    if (e.condition.holds(truth)) return e.target;
  throw std::logic_error("incomplete automaton: no edge for a letter");
}

int Dfa::step(int state, std::span<const int> true_props) const {
  // std::vector<bool> has no contiguous storage to view, hence the small bool array.
  std::unique_ptr<bool[]> truth(new bool[propositions.size()]());
  for (int p : true_props) {
    if (p < 0 || static_cast<std::size_t>(p) >= propositions.size())
      throw std::out_of_range("proposition index out of range");
    truth[static_cast<std::size_t>(p)] = true;
  }
  return step_by_truth(state, std::span<const bool>(truth.get(), propositions.size()));
}

bool Dfa::accepts(std::span<const std::vector<int>> trace) const {
  int state = start;
  for (const std::vector<int>& letter : trace) state = step(state, letter);
  return accepting.at(static_cast<std::size_t>(state));
}

}  // namespace physltl::ltl
