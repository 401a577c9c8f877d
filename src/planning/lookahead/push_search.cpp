#include "lookahead/push_search.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <queue>
#include <set>
#include <unordered_map>

namespace physltl::planning::lookahead {
namespace {

constexpr int kNever = std::numeric_limits<int>::max();

struct Node {
  std::vector<int> cells;
  int robot = 0;  // the smallest place the robot can walk to: the arrangement's robot component
  int stage = 0;
  int parent = -1;
  PushStep step;
  int pushes = 0;
};

std::string key_of(const std::vector<int>& cells, int robot, int stage) {
  std::string key;
  key.reserve((cells.size() + 2) * sizeof(std::int32_t));
  const auto put = [&](int v) { key.append(reinterpret_cast<const char*>(&v), sizeof v); };
  for (int c : cells) put(c);
  put(robot);
  put(stage);
  return key;
}

// The places the robot can walk to from `from` without entering one a body holds (holder[c] >= 0),
// marked with `mark` in `seen`; returns the smallest.
int walk(const PushLattice& lattice, int from, const std::vector<int>& holder, std::vector<int>& seen, int mark,
         std::vector<int>& queue) {
  queue.clear();
  queue.push_back(from);
  seen[static_cast<std::size_t>(from)] = mark;
  int smallest = from;
  for (std::size_t i = 0; i < queue.size(); ++i) {
    const int c = queue[i];
    smallest = std::min(smallest, c);
    for (int d = 0; d < kDirections; ++d) {
      if (!lattice.robot_passes(c, d)) continue;
      const int next = lattice.neighbour(c, d);
      if (seen[static_cast<std::size_t>(next)] == mark || holder[static_cast<std::size_t>(next)] >= 0) continue;
      seen[static_cast<std::size_t>(next)] = mark;
      queue.push_back(next);
    }
  }
  return smallest;
}

}  // namespace

PushSearcher::PushSearcher(const PushLattice& lattice, const StageGraph& stages, const Labelling& labelling)
    : lattice_(lattice), stages_(stages), labelling_(labelling) {}

bool PushSearcher::is_goal(int stage) const {
  const int distance = stages_.distance(stage);
  return distance == 0 || (distance > 0 && !stages_.body_move(stage));
}

int PushSearcher::facts_of(int stage, const std::vector<int>& cells) const {
  int facts = stages_.facts_of(stage);
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const int named = lattice_.named(static_cast<int>(k));
    if (named >= 0) facts = labelling_.with_place(facts, named, lattice_.place(static_cast<int>(k), cells[k]));
  }
  return facts;
}

PushSearcher::Goals PushSearcher::goals_from(int stage) const {
  const int bodies = static_cast<int>(lattice_.bodies().size());
  // The places each named body has in some fact set that would end the pushing from `stage`.
  std::vector<std::set<int>> wanted(static_cast<std::size_t>(bodies));
  for (int facts = 0; facts < labelling_.fact_sets(); ++facts) {
    if (!is_goal(stages_.after_letter(stage, labelling_.letter(facts, -1)))) continue;
    for (int k = 0; k < bodies; ++k) {
      if (lattice_.named(k) >= 0) wanted[static_cast<std::size_t>(k)].insert(labelling_.place(facts, lattice_.named(k)));
    }
  }
  Goals goals;
  goals.pushes_left.resize(static_cast<std::size_t>(bodies));
  for (int k = 0; k < bodies; ++k) {
    const std::set<int>& places = wanted[static_cast<std::size_t>(k)];
    if (lattice_.named(k) < 0 || places.empty() || places.count(0) > 0) continue;  // free: anywhere will do
    // Backwards from the wanted places: the body comes to `c` from `c - d`, pushed by a robot at `c - 2d`.
    std::vector<int> left(static_cast<std::size_t>(lattice_.cells()), kNever);
    std::vector<int> queue;
    for (int c = 0; c < lattice_.cells(); ++c) {
      if (lattice_.body_fits(k, c) && places.count(lattice_.place(k, c)) > 0) left[static_cast<std::size_t>(c)] = 0, queue.push_back(c);
    }
    for (std::size_t i = 0; i < queue.size(); ++i) {
      const int c = queue[i];
      for (int d = 0; d < kDirections; ++d) {
        if (!lattice_.can_push(k, d)) continue;
        const int before = lattice_.neighbour(c, opposite(d));
        if (before < 0 || !lattice_.body_fits(k, before) || left[static_cast<std::size_t>(before)] != kNever) continue;
        const int stand = lattice_.neighbour(before, opposite(d));
        if (stand < 0 || !lattice_.robot_fits(stand)) continue;
        left[static_cast<std::size_t>(before)] = left[static_cast<std::size_t>(c)] + 1;
        queue.push_back(before);
      }
    }
    goals.pushes_left[static_cast<std::size_t>(k)] = std::move(left);
  }
  return goals;
}

bool PushSearcher::alive(int stage, int k, int cell) const {
  const Goals goals = goals_from(stage);
  const auto& left = goals.pushes_left[static_cast<std::size_t>(k)];
  return left.empty() || left[static_cast<std::size_t>(cell)] != kNever;
}

bool PushSearcher::square_frozen(const Goals& goals, const std::vector<int>& cells, const std::vector<int>& holder,
                                 int at) const {
  const auto blocked = [&](int c) { return c < 0 || holder[static_cast<std::size_t>(c)] >= 0 || !lattice_.robot_fits(c); };
  const auto misplaced = [&](int c) {
    if (c < 0) return false;
    const int k = holder[static_cast<std::size_t>(c)];
    if (k < 0) return false;
    const auto& left = goals.pushes_left[static_cast<std::size_t>(k)];
    return !left.empty() && left[static_cast<std::size_t>(cells[static_cast<std::size_t>(k)])] != 0;
  };
  // The four squares of places that hold `at`: `at` and its neighbours across x and y and diagonally.
  for (int dx : {0, 1}) {
    for (int dy : {2, 3}) {
      const int side = lattice_.neighbour(at, dx);
      const int up = lattice_.neighbour(at, dy);
      const int corner = side < 0 ? -1 : lattice_.neighbour(side, dy);
      const int square[4] = {at, side, up, corner};
      if (!std::all_of(std::begin(square), std::end(square), blocked)) continue;
      if (std::any_of(std::begin(square), std::end(square), misplaced)) return true;
    }
  }
  return false;
}

PushSearch PushSearcher::search(int stage, const std::vector<int>& cells, int robot_cell,
                                long long max_arrangements) const {
  PushSearch result;
  const Goals goals = goals_from(stage);
  const auto estimate = [&](const std::vector<int>& at) {
    int sum = 0;
    for (std::size_t k = 0; k < at.size(); ++k) {
      const auto& left = goals.pushes_left[k];
      if (!left.empty()) sum += left[static_cast<std::size_t>(at[k])];
    }
    return sum;
  };
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const auto& left = goals.pushes_left[k];
    if (!left.empty() && left[static_cast<std::size_t>(cells[k])] == kNever) {
      result.outcome = "no order of pushes";
      return result;
    }
  }
  std::vector<int> holder(static_cast<std::size_t>(lattice_.cells()), -1);
  std::vector<int> seen(static_cast<std::size_t>(lattice_.cells()), -1);       // the robot's reach before a push
  std::vector<int> seen_after(static_cast<std::size_t>(lattice_.cells()), -1);  // and after it
  std::vector<int> queue;
  int mark = 0;
  const auto hold = [&](const std::vector<int>& at) {
    std::fill(holder.begin(), holder.end(), -1);
    for (std::size_t k = 0; k < at.size(); ++k) holder[static_cast<std::size_t>(at[k])] = static_cast<int>(k);
  };

  std::vector<Node> nodes;
  std::unordered_map<std::string, int> known;
  using Entry = std::tuple<double, long long, int>;  // priority, order of insertion, node
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  long long order = 0;
  hold(cells);
  Node root{cells, walk(lattice_, robot_cell, holder, seen, mark++, queue), stage, -1, {}, 0};
  known.emplace(key_of(root.cells, root.robot, root.stage), 0);
  nodes.push_back(root);
  open.push({kHeuristicWeight * estimate(cells), order++, 0});
  int solution = is_goal(stage) ? 0 : -1;
  while (solution < 0 && !open.empty()) {
    const int index = std::get<2>(open.top());
    open.pop();
    if (++result.settled > max_arrangements) {
      result.outcome = "search limit";
      return result;
    }
    const Node node = nodes[static_cast<std::size_t>(index)];
    hold(node.cells);
    walk(lattice_, node.robot, holder, seen, mark, queue);
    const int reach = mark++;
    for (std::size_t k = 0; k < node.cells.size() && solution < 0; ++k) {
      const int at = node.cells[k];
      for (int d = 0; d < kDirections && solution < 0; ++d) {
        if (!lattice_.can_push(static_cast<int>(k), d)) continue;
        const int stand = lattice_.neighbour(at, opposite(d));
        const int to = lattice_.neighbour(at, d);
        if (stand < 0 || to < 0 || seen[static_cast<std::size_t>(stand)] != reach) continue;
        if (!lattice_.body_fits(static_cast<int>(k), to) || holder[static_cast<std::size_t>(to)] >= 0) continue;
        const auto& left = goals.pushes_left[k];
        if (!left.empty() && left[static_cast<std::size_t>(to)] == kNever) continue;
        std::vector<int> next = node.cells;
        next[k] = to;
        const int next_stage = stages_.after_letter(node.stage, labelling_.letter(facts_of(node.stage, next), -1));
        if (stages_.distance(next_stage) < 0 || stages_.dead(stages_.automaton_state_of(next_stage))) continue;
        holder[static_cast<std::size_t>(at)] = -1;
        holder[static_cast<std::size_t>(to)] = static_cast<int>(k);
        const bool frozen = square_frozen(goals, next, holder, to);
        const int robot = frozen ? 0 : walk(lattice_, at, holder, seen_after, mark++, queue);
        holder[static_cast<std::size_t>(to)] = -1;
        holder[static_cast<std::size_t>(at)] = static_cast<int>(k);
        if (frozen) continue;
        const auto [it, inserted] = known.emplace(key_of(next, robot, next_stage), static_cast<int>(nodes.size()));
        if (!inserted) continue;
        nodes.push_back({std::move(next), robot, next_stage, index, {static_cast<int>(k), d, at, to}, node.pushes + 1});
        const Node& added = nodes.back();
        if (is_goal(added.stage)) {
          solution = it->second;
          break;
        }
        open.push({added.pushes + kHeuristicWeight * estimate(added.cells), order++, it->second});
      }
    }
  }
  if (solution < 0) {
    result.outcome = "no order of pushes";
    return result;
  }
  for (int n = solution; nodes[static_cast<std::size_t>(n)].parent >= 0; n = nodes[static_cast<std::size_t>(n)].parent) {
    result.steps.push_back(nodes[static_cast<std::size_t>(n)].step);
  }
  std::reverse(result.steps.begin(), result.steps.end());
  result.found = true;
  result.outcome = "found";
  return result;
}

}  // namespace physltl::planning::lookahead
