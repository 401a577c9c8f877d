#include "push_search.h"

#include "arrangement_store.h"
#include "goal_room.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <deque>
#include <limits>
#include <map>
#include <memory>
#include <queue>
#include <set>
#include <unordered_map>

namespace physltl::planners::knowledge::lookahead {
namespace {

constexpr int kNever = std::numeric_limits<int>::max();

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

// `seed` with `n` places from `first` mixed in: the hash of an arrangement's places.
std::size_t mix_places(std::size_t seed, const int* first, std::size_t n) {
  for (std::size_t k = 0; k < n; ++k) seed = seed * 1'000'003 ^ static_cast<std::size_t>(first[k]);
  return seed;
}

// Body k on `cells` (`holder`: per place, the body covering it or -1) and the bodies it would push in
// direction d, each the first time it stands in the way of one before it: for unit bodies, those end to
// end ahead of it.
std::vector<int> line_ahead(const PushLattice& lattice, const std::vector<int>& cells, const std::vector<int>& holder, int k, int d) {
  std::vector<int> line{k};
  for (std::size_t i = 0; i < line.size(); ++i) {
    lattice.for_each_cover(line[i], cells[static_cast<std::size_t>(line[i])], [&](int c) {
      const int ahead = lattice.neighbour(c, d);
      const int held = ahead < 0 ? -1 : holder[static_cast<std::size_t>(ahead)];
      if (held >= 0 && std::find(line.begin(), line.end(), held) == line.end()) line.push_back(held);
    });
  }
  return line;
}

}  // namespace

long long run_arrangements(double time_limit_s) {
  if (!(time_limit_s > 0.0) || time_limit_s * kArrangementsPerSecond >= static_cast<double>(kMaxArrangements)) return kMaxArrangements;
  return std::max(kPreviewArrangements, static_cast<long long>(time_limit_s * kArrangementsPerSecond));
}

PushSearcher::PushSearcher(const PushLattice& lattice, const planning::StageGraph& stages, const physltl::knowledge::Labelling& labelling)
    : lattice_(lattice), stages_(stages), labelling_(labelling) {}

bool PushSearcher::ends_pushing(int stage) const {
  const int distance = stages_.distance(stage);
  return distance == 0 || (distance > 0 && !stages_.body_move(stage));
}

int PushSearcher::facts_of(int stage, const std::vector<int>& cells) const {
  int facts = stages_.facts_of(stage);
  // A part's place is its bodies' common place: a group is in a region set only when all of it is.
  std::vector<int> place(labelling_.named_parts().size(), -1);
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const int named = lattice_.named(static_cast<int>(k));
    if (named < 0) continue;
    const int here = lattice_.place(static_cast<int>(k), cells[k]);
    int& common = place[static_cast<std::size_t>(named)];
    common = common < 0 || common == here ? here : 0;
  }
  for (std::size_t i = 0; i < place.size(); ++i) {
    if (place[i] >= 0) facts = labelling_.with_place(facts, static_cast<int>(i), place[i]);
  }
  return facts;
}

std::vector<int> PushSearcher::pushes_to(int k, const std::set<int>& places) const {
  std::vector<int> targets;
  for (int c = 0; c < lattice_.cells(); ++c) {
    if (lattice_.body_fits(k, c) && places.count(lattice_.place(k, c)) > 0) targets.push_back(c);
  }
  return pushes_to_cells(k, targets);
}

std::vector<int> PushSearcher::pushes_to_cells(int k, const std::vector<int>& targets) const {
  // Backwards from the targets: the body comes to `c` from `c - d`, pushed by a robot behind it (at
  // `c - 2d` for a unit body).
  std::vector<int> left(static_cast<std::size_t>(lattice_.cells()), kNever);
  std::vector<int> queue = targets;
  for (int c : targets) left[static_cast<std::size_t>(c)] = 0;
  for (std::size_t i = 0; i < queue.size(); ++i) {
    const int c = queue[i];
    for (int d = 0; d < kDirections; ++d) {
      if (!lattice_.can_push(k, d)) continue;
      const int before = lattice_.neighbour(c, opposite(d));
      if (before < 0 || !lattice_.body_fits(k, before) || left[static_cast<std::size_t>(before)] != kNever) continue;
      if (lattice_.first_stand(k, before, d, [&](int stand) { return lattice_.robot_fits(stand); }) < 0) continue;
      left[static_cast<std::size_t>(before)] = left[static_cast<std::size_t>(c)] + 1;
      queue.push_back(before);
    }
  }
  return left;
}

PushSearcher::Goals PushSearcher::goals_from(int stage, const base::Deadline& deadline) const {
  const int bodies = static_cast<int>(lattice_.bodies().size());
  // The places of the named bodies in each fact set that would end the pushing from `stage`.
  std::set<std::vector<int>> endings;
  for (int facts = 0; facts < labelling_.fact_sets(); ++facts) {
    if (!ends_pushing(stages_.after_letter(stage, labelling_.letter(facts, -1)))) continue;
    std::vector<int> ending(static_cast<std::size_t>(bodies), 0);
    for (int k = 0; k < bodies; ++k) {
      if (lattice_.named(k) >= 0) ending[static_cast<std::size_t>(k)] = labelling_.place(facts, lattice_.named(k));
    }
    endings.insert(std::move(ending));
  }
  Goals goals;
  goals.pushes_left.resize(static_cast<std::size_t>(bodies));
  std::vector<std::set<int>> wanted(static_cast<std::size_t>(bodies));
  for (const std::vector<int>& ending : endings) {
    for (int k = 0; k < bodies; ++k) wanted[static_cast<std::size_t>(k)].insert(ending[static_cast<std::size_t>(k)]);
  }
  for (int k = 0; k < bodies; ++k) {
    const std::set<int>& places = wanted[static_cast<std::size_t>(k)];
    if (lattice_.named(k) < 0 || places.empty() || places.count(0) > 0) continue;  // free: anywhere will do
    goals.pushes_left[static_cast<std::size_t>(k)] = pushes_to(k, places);
  }
  if (endings.size() > static_cast<std::size_t>(kMaxEndings)) return goals;
  goals.endings.assign(endings.begin(), endings.end());
  goals.pushes_to_place.resize(static_cast<std::size_t>(bodies));
  for (int k = 0; k < bodies; ++k) {
    if (lattice_.named(k) < 0) continue;
    for (int place : wanted[static_cast<std::size_t>(k)]) {
      auto& tables = goals.pushes_to_place[static_cast<std::size_t>(k)];
      if (tables.size() <= static_cast<std::size_t>(place)) tables.resize(static_cast<std::size_t>(place) + 1);
      // Place 0 is outside the body's regions: being there costs no push this bound counts.
      if (place > 0) tables[static_cast<std::size_t>(place)] = pushes_to(k, {place});
    }
  }
  add_matchings(goals, deadline);
  return goals;
}

void PushSearcher::add_matchings(Goals& goals, const base::Deadline& deadline) const {
  const int bodies = static_cast<int>(lattice_.bodies().size());
  goals.matched.assign(static_cast<std::size_t>(bodies), false);
  std::set<std::pair<int, int>> wanted;  // (part, place) of the groups some ending wants in a region set
  for (const std::vector<int>& ending : goals.endings) {
    for (int k = 0; k < bodies; ++k) {
      const int part = lattice_.named(k);
      if (part >= 0 && labelling_.named_parts()[static_cast<std::size_t>(part)].bodies.size() > 1) {
        goals.matched[static_cast<std::size_t>(k)] = true;
        if (ending[static_cast<std::size_t>(k)] > 0) wanted.insert({part, ending[static_cast<std::size_t>(k)]});
      }
    }
  }
  for (const auto& part_and_place : wanted) {
    // Not a structured binding: Clang 14 (Debian 12's) refuses one captured by the lambda below.
    const int part = part_and_place.first;
    const int place = part_and_place.second;
    Goals::Matching matching{part, place, {}, {}, {}};
    for (int k = 0; k < bodies; ++k) {
      if (lattice_.named(k) == part) matching.bodies.push_back(k);
    }
    for (int c = 0; c < lattice_.cells(); ++c) {
      const bool fits = std::any_of(matching.bodies.begin(), matching.bodies.end(),
                                    [&](int k) { return lattice_.body_fits(k, c) && lattice_.place(k, c) == place; });
      if (fits) matching.targets.push_back(c);
    }
    const std::size_t targets = matching.targets.size();
    for (int k : matching.bodies) {
      auto& table = matching.pushes.emplace_back(static_cast<std::size_t>(lattice_.cells()) * targets, kNever);
      for (std::size_t j = 0; j < targets; ++j) {
        if (!lattice_.body_fits(k, matching.targets[j])) continue;
        deadline.check();
        const std::vector<int> to_target = pushes_to_cells(k, {matching.targets[j]});
        for (std::size_t c = 0; c < to_target.size(); ++c) table[c * targets + j] = to_target[c];
      }
    }
    goals.matchings.push_back(std::move(matching));
  }
}

int PushSearcher::estimate(int stage, const std::vector<int>& cells) const { return goals_from(stage).estimate(cells); }

bool PushSearcher::alive(int stage, int k, int cell) const {
  return goals_from(stage).left(k, cell) != kNever;
}

int PushSearcher::Goals::left(int k, int cell) const {
  const auto& table = pushes_left[static_cast<std::size_t>(k)];
  return table.empty() ? 0 : table[static_cast<std::size_t>(cell)];
}

int PushSearcher::Goals::Matching::cost(const std::vector<int>& cells, std::vector<int>& matrix, geometry::Assignment& assignment) const {
  const int rows = static_cast<int>(bodies.size()), columns = static_cast<int>(targets.size());
  matrix.resize(static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns));
  for (int i = 0; i < rows; ++i) {
    const auto cell = static_cast<std::size_t>(cells[static_cast<std::size_t>(bodies[static_cast<std::size_t>(i)])]);
    const auto row = pushes[static_cast<std::size_t>(i)].begin() + static_cast<std::ptrdiff_t>(cell * static_cast<std::size_t>(columns));
    std::copy(row, row + columns, matrix.begin() + static_cast<std::ptrdiff_t>(i) * columns);
  }
  if (rows <= kMaxMatchedBodies) return assignment.cheapest(matrix, rows, columns, kNever);
  if (rows > columns) return kNever;
  long long by_body = 0, by_place = 0;
  for (int i = 0; i < rows; ++i) by_body += *std::min_element(matrix.begin() + i * columns, matrix.begin() + (i + 1) * columns);
  for (int j = 0; j < columns && rows == columns; ++j) {
    int cheapest = kNever;
    for (int i = 0; i < rows; ++i) cheapest = std::min(cheapest, matrix[static_cast<std::size_t>(i * columns + j)]);
    by_place += cheapest;
  }
  const long long bound = std::max(by_body, by_place);
  return bound >= kNever ? kNever : static_cast<int>(bound);
}

int PushSearcher::Goals::estimate(const std::vector<int>& cells) const {
  int apart = 0;
  for (std::size_t k = 0; k < cells.size(); ++k) apart += left(static_cast<int>(k), cells[k]);
  if (endings.empty()) return apart;
  int best = kNever;
  for (const std::vector<int>& ending : endings) {
    int sum = 0;
    for (std::size_t k = 0; k < cells.size() && sum < best; ++k) {
      const int place = ending[k];
      if (place == 0 || pushes_to_place[k].empty() || matched[k]) continue;
      const int pushes = pushes_to_place[k][static_cast<std::size_t>(place)][static_cast<std::size_t>(cells[k])];
      sum = pushes == kNever ? kNever : sum + pushes;
    }
    for (const Matching& m : matchings) {
      if (sum >= best) break;
      if (ending[static_cast<std::size_t>(m.bodies.front())] != m.place) continue;
      const int pushes = m.cost(cells, scratch_, assignment_);
      sum = pushes == kNever ? kNever : sum + pushes;
    }
    best = std::min(best, sum);
  }
  // Every ending out of reach alone: the arrangement is pruned elsewhere, or the bodies must help each other.
  return best == kNever ? apart : std::max(best, apart);
}

int PushSearcher::stage_after(int stage, const std::vector<int>& cells) const {
  return stages_.after_letter(stage, labelling_.letter(facts_of(stage, cells), -1));
}

bool PushSearcher::square_frozen(const Goals& goals, const std::vector<int>& cells, const std::vector<int>& holder, int at) const {
  const auto blocked = [&](int c) { return c < 0 || holder[static_cast<std::size_t>(c)] >= 0 || !lattice_.robot_fits(c); };
  const auto misplaced = [&](int c) {
    if (c < 0) return false;
    const int k = holder[static_cast<std::size_t>(c)];
    if (k < 0) return false;
    return goals.left(k, cells[static_cast<std::size_t>(k)]) != 0;
  };
  const auto body = [&](int c) { return c >= 0 && holder[static_cast<std::size_t>(c)] >= 0; };
  // The four squares of places that hold `at`: `at` and its neighbours across x and y and diagonally.
  for (int dx : {0, 1}) {
    for (int dy : {2, 3}) {
      const int side = lattice_.neighbour(at, dx);
      const int up = lattice_.neighbour(at, dy);
      const int corner = side < 0 ? -1 : lattice_.neighbour(side, dy);
      const int square[4] = {at, side, up, corner};
      if (!std::all_of(std::begin(square), std::end(square), blocked)) continue;
      // Two bodies side by side in it may still move as a line, pushed end to end.
      if ((body(at) || body(corner)) && (body(side) || body(up))) continue;
      if (std::any_of(std::begin(square), std::end(square), misplaced)) return true;
    }
  }
  return false;
}

// A body is frozen when it can be pushed along neither axis again. Along an axis, each way is shut by
// the lattice (the body cannot be pushed that way: no side to push, no room ahead, no place behind for the
// robot, or a place from which it could never get where the task wants it), or by frozen bodies behind it
// (on every place the robot could push from) or ahead of it; a body already looked at counts as frozen (it
// stands in the way of the one that asked). Bodies ahead that the pushed one can move as a line leave the
// way open: a line may end an order. Bodies of several places alike, through the places they cover.
class FreezeTest {
 public:
  // `cells`: per lattice body, its place; `holder`: per place, the body covering it or -1.
  FreezeTest(const PushLattice& lattice, const PushSearcher::Goals& goals, const std::vector<int>& holder, const std::vector<int>& cells)
      : lattice_(lattice), goals_(goals), holder_(holder), cells_(cells) {}

  // Whether lattice body k is frozen with a body frozen with it (itself included) not where the task
  // wants it: an arrangement no push can resolve.
  bool deadlocked(int k) {
    looked_at_.clear();
    if (!frozen(k)) return false;
    return std::any_of(looked_at_.begin(), looked_at_.end(), [&](int j) { return goals_.left(j, place(j)) != 0; });
  }

 private:
  int place(int k) const { return cells_[static_cast<std::size_t>(k)]; }
  int holder(int c) const { return c < 0 ? -1 : holder_[static_cast<std::size_t>(c)]; }

  bool frozen(int k) {
    looked_at_.push_back(k);
    return axis_shut(k, 0) && axis_shut(k, 2);
  }

  // Both ways along the axis of direction d shut.
  bool axis_shut(int k, int d) { return way_shut(k, d) && way_shut(k, opposite(d)); }

  bool way_shut(int k, int d) {
    const int at = place(k);
    const int to = lattice_.neighbour(at, d);
    const auto fits = [&](int stand) { return lattice_.robot_fits(stand); };
    if (!lattice_.can_push(k, d) || to < 0 || lattice_.first_stand(k, at, d, fits) < 0) return true;
    if (!lattice_.body_fits(k, to) || goals_.left(k, to) == kNever) return true;
    // Every place the robot could push from held by a body that stays.
    const auto open = [&](int stand) { return fits(stand) && (holder(stand) < 0 || !stops(holder(stand))); };
    if (lattice_.first_stand(k, at, d, open) < 0) return true;
    bool blocked = false;
    lattice_.for_each_cover(k, to, [&](int c) {
      const int ahead = holder(c);
      blocked = blocked || (ahead >= 0 && ahead != k && stops(ahead));
    });
    return blocked && !line_moves(k, d);
  }

  // Whether the body k stands in the way for good: looked at already, or frozen.
  bool stops(int k) {
    if (std::find(looked_at_.begin(), looked_at_.end(), k) != looked_at_.end()) return true;
    const std::size_t mark = looked_at_.size();
    if (frozen(k)) return true;
    looked_at_.resize(mark);  // it may move: what it was frozen with is not
    return false;
  }

  // The bodies from k on in direction d (end to end; of several places, each the first time it stands
  // ahead of one before it), pushed together one place.
  bool line_moves(int k, int d) const {
    if (lattice_.unit_bodies()) {
      int c = place(k);
      while (holder(lattice_.neighbour(c, d)) >= 0) c = lattice_.neighbour(c, d);
      const int beyond = lattice_.neighbour(c, d);
      return beyond >= 0 && lattice_.body_fits(holder(c), beyond);
    }
    const std::vector<int> line = line_ahead(lattice_, cells_, holder_, k, d);
    return std::all_of(line.begin(), line.end(), [&](int j) {
      const int to = lattice_.neighbour(place(j), d);
      return to >= 0 && lattice_.body_fits(j, to);
    });
  }

  const PushLattice& lattice_;
  const PushSearcher::Goals& goals_;
  const std::vector<int>& holder_;
  const std::vector<int>& cells_;
  std::vector<int> looked_at_;  // the bodies looked at, frozen so far
};

// A corral: places the robot cannot walk to, closed off by bodies, and the bodies on its edge. Every other
// body taken off the lattice only frees places, so when the corral's bodies alone cannot all be pushed to
// where the task wants them, neither can they with the others there: the arrangement is a deadlock,
// though no body in it is frozen (the robot could push them, from inside the corral). The search over the
// corral's bodies allows every push the arrangement search makes (a line of them pushed one place
// included) and leaves out its stage and pruning rules, so it finds a way wherever that one could. It
// looks for an arrangement with every corral body where the task wants it (an order ends on one, all at
// once) or with the robot able to walk into the corral (no corral any more: searching on from there cost
// more than it pruned, docs/planner.md); it decides only when it settles every arrangement of those
// bodies, within kCorralArrangements, without one.
struct PlacesHash {
  std::size_t operator()(const std::vector<int>& places) const { return mix_places(places.size(), places.data(), places.size()); }
};

class CorralTest {
 public:
  static constexpr int kCorralArrangements = 64;
  static constexpr std::size_t kMaxCorralBodies = 5;

  // Verdicts of earlier tests, by the corral's bodies, their places and the robot's place: the same corral
  // comes back in many arrangements that differ elsewhere.
  using Verdicts = std::unordered_map<std::vector<int>, bool, PlacesHash>;

  // `cells`: per lattice body, its place (held in `holder`); `reach`: the places the robot can walk to,
  // marked `reached`.
  CorralTest(const PushLattice& lattice, const PushSearcher::Goals& goals, const std::vector<int>& holder,
             const std::vector<int>& cells, const std::vector<int>& reach, int reached, Verdicts& verdicts)
      : verdicts_(verdicts),
        lattice_(lattice),
        goals_(goals),
        holder_(holder),
        cells_(cells),
        reach_(reach),
        reached_(reached),
        seen_(static_cast<std::size_t>(lattice.cells()), -1) {}

  // Whether the corrals holding the places `seeds` (where the robot on `robot_cell` cannot walk) make the
  // arrangement a deadlock. Only a corral the robot can change from outside by pushing its bodies in
  // (every push from where it can walk moves a body into the corral) is searched: the robot can push
  // the other corrals' bodies out, which the arrangement search tries anyway.
  bool deadlocked(int robot_cell, const std::vector<int>& seeds) {
    const std::vector<int> bodies = corral_bodies(seeds);
    if (bodies.empty() || bodies.size() > kMaxCorralBodies) return false;
    std::vector<int> cells;
    for (int k : bodies) cells.push_back(cells_[static_cast<std::size_t>(k)]);
    if (placed(bodies, cells) || pushes_out(bodies)) return false;
    std::vector<int> key = bodies;
    key.insert(key.end(), cells.begin(), cells.end());
    key.push_back(robot_cell);
    const auto known = verdicts_.find(key);
    if (known != verdicts_.end()) return known->second;
    const bool dead = !way_out(bodies, cells, robot_cell);
    verdicts_.emplace(std::move(key), dead);
    return dead;
  }

 private:
  // Whether the robot, from where it can walk, can push a corral body to a place outside the corral.
  bool pushes_out(const std::vector<int>& bodies) const {
    for (int k : bodies) {
      const int at = cells_[static_cast<std::size_t>(k)];
      for (int d = 0; d < kDirections; ++d) {
        const int stand = lattice_.neighbour(at, opposite(d));
        const int to = lattice_.neighbour(at, d);
        if (stand < 0 || to < 0 || reach_[static_cast<std::size_t>(stand)] != reached_ || !lattice_.can_push(k, d)) continue;
        if (holder_[static_cast<std::size_t>(to)] >= 0 || !lattice_.body_fits(k, to) || goals_.left(k, to) == kNever) continue;
        if (seen_[static_cast<std::size_t>(to)] != corral_) return true;
      }
    }
    return false;
  }

  // The bodies next to the places the robot cannot walk to from `seeds` on, in lattice order.
  std::vector<int> corral_bodies(const std::vector<int>& seeds) {
    std::vector<int> queue, bodies;
    const int mark = corral_ = mark_++;
    for (int c : seeds) {
      if (seen_[static_cast<std::size_t>(c)] != mark) seen_[static_cast<std::size_t>(c)] = mark, queue.push_back(c);
    }
    for (std::size_t i = 0; i < queue.size(); ++i) {
      const int c = queue[i];
      for (int d = 0; d < kDirections; ++d) {
        const int next = lattice_.neighbour(c, d);
        if (next < 0) continue;
        const int k = holder_[static_cast<std::size_t>(next)];
        if (k >= 0) {
          if (std::find(bodies.begin(), bodies.end(), k) == bodies.end()) bodies.push_back(k);
        } else if (lattice_.robot_passes(c, d) && seen_[static_cast<std::size_t>(next)] != mark) {
          seen_[static_cast<std::size_t>(next)] = mark;
          queue.push_back(next);
        }
      }
    }
    std::sort(bodies.begin(), bodies.end());
    corral_places_ = std::move(queue);
    return bodies;
  }

  bool placed(const std::vector<int>& bodies, const std::vector<int>& cells) const {
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      if (goals_.left(bodies[i], cells[i]) != 0) return false;
    }
    return true;
  }

  // Breadth first over the arrangements of `bodies` alone on the lattice, from `cells` with the robot on
  // `robot_cell`: whether one has every body where the task wants it or the robot in the corral (or the
  // budget ran out first).
  bool way_out(const std::vector<int>& bodies, const std::vector<int>& cells, int robot_cell) {
    std::vector<int> holder(static_cast<std::size_t>(lattice_.cells()), -1), queue;
    std::set<std::vector<int>> met;
    // An arrangement met, with whether the robot can walk behind each body for each direction (body i,
    // direction d at i * kDirections + d), found by the walk that told it apart.
    struct Met {
      std::vector<int> cells;
      std::vector<bool> stands;
    };
    std::deque<Met> open;
    const auto meet = [&](const std::vector<int>& at, int robot) {
      for (std::size_t i = 0; i < at.size(); ++i) holder[static_cast<std::size_t>(at[i])] = static_cast<int>(i);
      const int reach = mark_++;
      std::vector<int> key = at;
      key.push_back(walk(lattice_, robot, holder, seen_, reach, queue));
      for (int c : at) holder[static_cast<std::size_t>(c)] = -1;
      if (!met.insert(std::move(key)).second) return false;
      // The robot walks into the corral: it is a corral no more, and what happens in it is the
      // arrangement search's to find.
      for (int c : corral_places_) {
        if (seen_[static_cast<std::size_t>(c)] == reach) return true;
      }
      Met entry{at, std::vector<bool>(at.size() * kDirections, false)};
      for (std::size_t i = 0; i < at.size(); ++i) {
        for (int d = 0; d < kDirections; ++d) {
          const int stand = lattice_.neighbour(at[i], opposite(d));
          entry.stands[i * kDirections + static_cast<std::size_t>(d)] = stand >= 0 && seen_[static_cast<std::size_t>(stand)] == reach;
        }
      }
      open.push_back(std::move(entry));
      return false;
    };
    if (meet(cells, robot_cell)) return true;
    while (!open.empty()) {
      if (static_cast<int>(met.size()) > kCorralArrangements) return true;
      const Met from = std::move(open.front());
      open.pop_front();
      for (std::size_t i = 0; i < from.cells.size(); ++i) holder[static_cast<std::size_t>(from.cells[i])] = static_cast<int>(i);
      std::vector<std::pair<std::vector<int>, int>> pushed;  // the arrangement, and the robot where the body was
      for (std::size_t i = 0; i < from.cells.size(); ++i) {
        for (int d = 0; d < kDirections; ++d) {
          std::vector<int> next = from.cells;
          if (from.stands[i * kDirections + static_cast<std::size_t>(d)] && push(bodies, holder, next, static_cast<int>(i), d)) {
            pushed.emplace_back(std::move(next), from.cells[i]);
          }
        }
      }
      for (int c : from.cells) holder[static_cast<std::size_t>(c)] = -1;
      for (auto& [next, robot] : pushed) {
        if (placed(bodies, next) || meet(next, robot)) return true;
      }
    }
    return false;
  }

  // Body i of `cells` pushed one place in direction d, with the bodies in a line ahead of it, by a robot
  // behind it: into `cells`, or false.
  bool push(const std::vector<int>& bodies, const std::vector<int>& holder, std::vector<int>& cells, int i, int d) const {
    const int at = cells[static_cast<std::size_t>(i)];
    std::vector<int> line{i};
    for (int c = lattice_.neighbour(at, d); c >= 0 && holder[static_cast<std::size_t>(c)] >= 0; c = lattice_.neighbour(c, d)) {
      line.push_back(holder[static_cast<std::size_t>(c)]);
    }
    for (int j : line) {
      const int body = bodies[static_cast<std::size_t>(j)];
      const int to = lattice_.neighbour(cells[static_cast<std::size_t>(j)], d);
      if (!lattice_.can_push(body, d) || to < 0 || !lattice_.body_fits(body, to)) return false;
      cells[static_cast<std::size_t>(j)] = to;
    }
    return line.size() > 1 || goals_.left(bodies[static_cast<std::size_t>(i)], cells[static_cast<std::size_t>(i)]) != kNever;
  }

  Verdicts& verdicts_;
  const PushLattice& lattice_;
  const PushSearcher::Goals& goals_;
  const std::vector<int>& holder_;
  const std::vector<int>& cells_;  // per lattice body, its place
  const std::vector<int>& reach_;
  int reached_;
  std::vector<int> seen_;
  int mark_ = 0;
  int corral_ = -1;  // the mark of the corral's places in seen_
  std::vector<int> corral_places_;
};

bool PushSearcher::corralled(int stage, const std::vector<int>& cells, int robot_cell) const {
  std::vector<int> holder(static_cast<std::size_t>(lattice_.cells()), -1), seen(holder.size(), -1), queue;
  for (std::size_t j = 0; j < cells.size(); ++j) holder[static_cast<std::size_t>(cells[j])] = static_cast<int>(j);
  walk(lattice_, robot_cell, holder, seen, 0, queue);
  std::vector<int> seeds;
  for (int c = 0; c < lattice_.cells(); ++c) {
    if (holder[static_cast<std::size_t>(c)] < 0 && lattice_.robot_fits(c) && seen[static_cast<std::size_t>(c)] != 0) seeds.push_back(c);
  }
  const Goals goals = goals_from(stage);
  CorralTest::Verdicts verdicts;
  return CorralTest(lattice_, goals, holder, cells, seen, 0, verdicts).deadlocked(robot_cell, seeds);
}

bool PushSearcher::frozen_apart(int stage, const std::vector<int>& cells, int k) const {
  std::vector<int> holder(static_cast<std::size_t>(lattice_.cells()), -1);
  for (std::size_t j = 0; j < cells.size(); ++j) {
    lattice_.for_each_cover(static_cast<int>(j), cells[j], [&](int c) { holder[static_cast<std::size_t>(c)] = static_cast<int>(j); });
  }
  const Goals goals = goals_from(stage);
  return FreezeTest(lattice_, goals, holder, cells).deadlocked(k);
}

// One search's state: the arrangements met (ArrangementStore), the open ones by priority, and scratch
// space for the walks.
class ArrangementSearch {
 public:
  ArrangementSearch(const PushLattice& lattice, const planning::StageGraph& stages, const PushSearcher& searcher,
                    const PushSearcher::Goals& goals, double weight, const std::vector<int>& start_cells)
      : lattice_(lattice),
        stages_(stages),
        searcher_(searcher),
        goals_(goals),
        weight_(weight),
        holder_(static_cast<std::size_t>(lattice.cells()), -1),
        seen_(static_cast<std::size_t>(lattice.cells()), -1),
        seen_after_(static_cast<std::size_t>(lattice.cells()), -1),
        store_(start_cells) {}

  // Opens the arrangement to start from, the robot on `robot_cell`.
  void start(int robot_cell, int stage, const std::vector<int>& cells) {
    find_rooms(robot_cell);
    hold(cells);
    const int robot = walk(lattice_, robot_cell, holder_, seen_, mark_++, queue_);
    open(store_.add({ArrangementStore::kStart, robot, stage, 0, 0, 0}), 0, cells);
  }
  bool exhausted() const { return open_.empty(); }
  // Settles the open arrangement of highest priority: adds every arrangement one push away, and where a
  // body has others in a line ahead of it, the pushes of the line that end the pushing. Returns whether
  // one added ends the pushing; its order is then steps().
  bool settle() {
    const auto m = static_cast<int>(open_.top().met);
    open_.pop();
    const ArrangementStore::Met met = store_.met(m);
    const int cost = cost_of(m);
    const int settled = store_.settle(m, cost, cells_);
    hold(cells_);
    walk(lattice_, met.robot, holder_, seen_, mark_, queue_);
    const Expansion from{settled, met.stage, cost, mark_++};
    for (std::size_t k = 0; k < cells_.size(); ++k) {
      for (int d = 0; d < kDirections; ++d) {
        if (is_line(cells_, static_cast<int>(k), d)) {
          if (finish_with_line(from, static_cast<int>(k), d)) return true;
          continue;
        }
        for (const int added : push(from, static_cast<int>(k), d)) {
          if (added >= 0 && searcher_.ends_pushing(store_.met(added).stage)) {
            steps_ = steps_to(added);
            return true;
          }
        }
      }
    }
    return false;
  }
  const std::vector<PushStep>& steps() const { return steps_; }
  // The memory the search holds: the arrangements, the open list, the goal macros' ways and the corral
  // verdicts.
  std::size_t bytes() const {
    return store_.bytes() + open_.size() * sizeof(Open) + macro_bytes_ + corral_verdicts_.size() * kVerdictBytes;
  }

 private:
  // The settled arrangement being expanded (its places in cells_, the robot's reach marked `reach`).
  struct Expansion {
    int settled = 0, stage = 0, cost = 0, reach = 0;
  };
  // An open arrangement: priority, then the order it was met in (its number) to break ties.
  struct Open {
    float priority = 0.0F;  // integral in practice (pushes plus a whole multiple of them), so exact
    std::uint32_t met = 0;
    bool operator>(const Open& other) const { return priority != other.priority ? priority > other.priority : met > other.met; }
  };

  void open(int m, int cost, const std::vector<int>& cells) {
    if (m < 0) return;
    open_.push({static_cast<float>(cost + weight_ * goals_.estimate(cells)), static_cast<std::uint32_t>(m)});
  }

  void hold(const std::vector<int>& at) {
    std::fill(holder_.begin(), holder_.end(), -1);
    for (std::size_t k = 0; k < at.size(); ++k) mark(static_cast<int>(k), at[k], static_cast<int>(k));
  }
  // holder_ of the places body k covers on `cell` set to `to`.
  void mark(int k, int cell, int to) {
    lattice_.for_each_cover(k, cell, [&](int c) { holder_[static_cast<std::size_t>(c)] = to; });
  }
  // Whether body k moved to `to` covers only places no other body holds.
  bool room_for(int k, int to) const {
    bool free = true;
    lattice_.for_each_cover(k, to, [&](int c) { free &= holder_[static_cast<std::size_t>(c)] < 0 || holder_[static_cast<std::size_t>(c)] == k; });
    return free;
  }

  // Body k pushed from place `from` in direction d until it stands on `to`, one place at a time.
  std::vector<PushStep> straight_run(int k, int d, int from, int to) const {
    std::vector<PushStep> run;
    for (int at = from; at != to; at = lattice_.neighbour(at, d)) run.push_back({k, d, at, lattice_.neighbour(at, d), {}});
    return run;
  }
  // The pushes that made met arrangement m from its parent: its body, one place at a time.
  std::vector<PushStep> run_of(int m) const {
    const ArrangementStore::Met& met = store_.met(m);
    if (met.macro) return macro_runs_.at(m);
    if (met.parent == ArrangementStore::kStart) return {};
    return straight_run(met.body, met.direction, store_.settled_places(static_cast<int>(met.parent))[met.body], met.to);
  }
  // Its body steps so far: its parent's and as many as the places its push moved its body.
  int cost_of(int m) const {
    const ArrangementStore::Met& met = store_.met(m);
    if (met.parent == ArrangementStore::kStart) return 0;
    int steps = 0;
    if (met.macro) {
      steps = static_cast<int>(macro_runs_.at(m).size());
    } else {
      for (int at = store_.settled_places(static_cast<int>(met.parent))[met.body]; at != met.to; at = lattice_.neighbour(at, met.direction)) ++steps;
    }
    return store_.settled_cost(static_cast<int>(met.parent)) + steps;
  }
  // The order of pushes from the start to met arrangement m.
  std::vector<PushStep> steps_to(int m) const {
    std::vector<PushStep> steps;
    for (; store_.met(m).parent != ArrangementStore::kStart; m = store_.settled_met(static_cast<int>(store_.met(m).parent))) {
      const std::vector<PushStep> run = run_of(m);
      steps.insert(steps.end(), run.rbegin(), run.rend());
    }
    std::reverse(steps.begin(), steps.end());
    return steps;
  }

  // Whether body k pushed in direction d would move others: one covers a place it would move into.
  bool is_line(const std::vector<int>& cells, int k, int d) const {
    const int to = lattice_.neighbour(cells[static_cast<std::size_t>(k)], d);
    return to >= 0 && !room_for(k, to);
  }


  // The arrangement after pushing body k of `from` one step in direction d, added unless it was met
  // before or is pruned, and where that step takes the body into a goal room, the arrangement with it
  // pushed on to the room's deepest free goal place (into_room); their numbers, or -1. Pushed on through
  // a tunnel (in_tunnel), one arrangement.
  std::array<int, 2> push(const Expansion& from, int k, int d) {
    const std::vector<int>& cells = cells_;
    int at = cells[static_cast<std::size_t>(k)];
    if (!lattice_.can_push(k, d)) return {-1, -1};
    const int stand = lattice_.first_stand(k, at, d, [&](int c) { return seen_[static_cast<std::size_t>(c)] == from.reach; });
    int to = lattice_.neighbour(at, d);
    if (stand < 0 || to < 0) return {-1, -1};
    if (!lattice_.body_fits(k, to) || !room_for(k, to) || goals_.left(k, to) == kNever) return {-1, -1};
    std::vector<int> next = cells;
    next[static_cast<std::size_t>(k)] = to;
    const int next_stage = searcher_.stage_after(from.stage, next);
    if (stages_.distance(next_stage) < 0 || stages_.dead(stages_.automaton_state_of(next_stage))) return {-1, -1};
    int cost = from.cost + 1;
    // The robot ends on the place the body's face left, ahead of the one it pushed from (the body's place,
    // for a unit body).
    int robot_on = lattice_.neighbour(stand, d);
    while (in_tunnel(k, d, at, to, next, next_stage)) {
      at = to, to = lattice_.neighbour(to, d), ++cost;
      robot_on = at;
      next[static_cast<std::size_t>(k)] = to;
    }
    const int robot = settle_check(next, k, to, robot_on);
    if (robot < 0) return {-1, -1};
    const int added = store_.add({static_cast<std::uint32_t>(from.settled), robot, next_stage, to, static_cast<std::uint16_t>(k),
                                  static_cast<std::uint8_t>(d)});
    open(added, cost, next);
    return {added, into_room(from, k, d, to, next_stage)};
  }

  // Body k of `cells_` moved to `to` (the arrangement `next`), the robot on `robot_cell`: the robot's
  // component, or -1 when the move leaves a deadlock (square_frozen, FreezeTest, a corral).
  int settle_check(const std::vector<int>& next, int k, int to, int robot_cell) {
    const int before = cells_[static_cast<std::size_t>(k)];
    mark(k, before, -1);
    mark(k, to, k);
    // The square and corral rules are of unit bodies; a body of any shape is frozen or not.
    const bool unit = lattice_.unit_bodies();
    bool dead = (unit && searcher_.square_frozen(goals_, next, holder_, to)) || FreezeTest(lattice_, goals_, holder_, next).deadlocked(k);
    const int robot = dead ? 0 : walk(lattice_, robot_cell, holder_, seen_after_, mark_, queue_);
    if (!dead && unit) dead = corralled(next, to, robot_cell);
    ++mark_;
    mark(k, to, -1);
    mark(k, before, k);
    return dead ? -1 : robot;
  }

  // The goal rooms of each lattice body the task wants somewhere, one set per set of goal places.
  void find_rooms(int robot_cell) {
    std::map<std::vector<bool>, std::size_t> known;
    rooms_of_.assign(lattice_.bodies().size(), nullptr);
    for (std::size_t k = 0; k < lattice_.bodies().size() && lattice_.unit_bodies(); ++k) {
      if (goals_.pushes_left[k].empty()) continue;  // the task leaves it free: every place is one of its goal places
      std::vector<bool> goal(static_cast<std::size_t>(lattice_.cells()));
      for (int c = 0; c < lattice_.cells(); ++c) goal[static_cast<std::size_t>(c)] = goals_.left(static_cast<int>(k), c) == 0;
      const auto [it, added] = known.try_emplace(std::move(goal), rooms_.size());
      if (added) rooms_.push_back(std::make_unique<GoalRooms>(lattice_, it->first, robot_cell));
      if (rooms_[it->second]->size() > 0) rooms_of_[k] = rooms_[it->second].get();
    }
  }

  // The goal macro: body k, just pushed in direction d onto `entrance` (stage `stage`), a goal room's
  // entrance with the room ahead, pushed on by the fewest pushes inside the room (the robot walking
  // between them through the room) to the first goal place, deepest first, that is free and that it
  // can get to, every place on the way keeping the stage. One more successor: the search keeps the
  // others, so the macro only leads. Its number, or -1.
  int into_room(const Expansion& from, int k, int d, int entrance, int stage) {
    const GoalRooms* rooms = rooms_of_[static_cast<std::size_t>(k)];
    const GoalRoom* room = rooms == nullptr ? nullptr : rooms->entered(entrance, d);
    if (room == nullptr) return -1;
    const int before = cells_[static_cast<std::size_t>(k)];
    const auto may_stand = [&](int c) {
      return lattice_.body_fits(k, c) && holder_[static_cast<std::size_t>(c)] < 0 && goals_.left(k, c) != kNever;
    };
    const std::vector<int> way = room->way_in(lattice_, k, d, may_stand, [&](int c) { return holder_[static_cast<std::size_t>(c)] >= 0 && c != before; });
    if (way.empty()) return -1;
    // The steps: the body's run onto the entrance, then the way, one place at a time.
    std::vector<PushStep> run = straight_run(k, d, before, entrance);
    std::vector<int> next = cells_;
    int at = entrance;
    for (std::size_t i = 0; i < way.size(); ++i) {
      const int to = way[i];
      int direction = 0;
      while (lattice_.neighbour(at, direction) != to) ++direction;
      run.push_back({k, direction, at, to, {}});
      next[static_cast<std::size_t>(k)] = to;
      if (i + 1 < way.size() && searcher_.stage_after(stage, next) != stage) return -1;
      at = to;
    }
    const int final_stage = searcher_.stage_after(stage, next);
    if (stages_.distance(final_stage) < 0 || stages_.dead(stages_.automaton_state_of(final_stage))) return -1;
    const int goal = way.back();
    const int robot = settle_check(next, k, goal, run.back().from);
    if (robot < 0) return -1;
    const int added = store_.add({static_cast<std::uint32_t>(from.settled), robot, final_stage, goal, static_cast<std::uint16_t>(k),
                                  static_cast<std::uint8_t>(d), true});
    if (added < 0) return -1;
    const int cost = from.cost + static_cast<int>(run.size());
    macro_bytes_ += sizeof(PushStep) * run.size() + kMacroEntryBytes;
    macro_runs_.emplace(added, std::move(run));
    open(added, cost, next);
    return added;
  }

  // Whether body k, just pushed from `at` to `to` in direction d (the arrangement `next`, its stage
  // `stage`), is to be pushed on at once: a tunnel macro (Junghanns and Schaeffer's), kept short of the
  // tunnel's exit. The robot on `at` and the body on `to` each have walls on both sides across d, and so
  // has the place ahead, which is free, not where the task wants the body (nor is `to`), not dead, and
  // keeps the stage: from the body's place on to the next, nothing but the body's place in the passage changes (the
  // passage stays shut, the robot's reach the same on either side), and from the exit side the body can
  // be pushed back. The exit itself, a goal in the passage and a change of stage are left to the search.
  bool in_tunnel(int k, int d, int at, int to, const std::vector<int>& next, int stage) const {
    const auto walled = [&](int c) {
      for (int side : {0, 1}) {
        const int across = lattice_.neighbour(c, d < 2 ? 2 + side : side);
        if (across >= 0 && lattice_.robot_fits(across)) return false;
      }
      return true;
    };
    const int ahead = lattice_.neighbour(to, d);
    if (!lattice_.unit_bodies() || ahead < 0 || !walled(at) || !walled(to) || !walled(ahead)) return false;
    if (goals_.left(k, to) == 0) return false;  // where the task wants it: pushed on, it would leave
    if (!lattice_.body_fits(k, ahead) || holder_[static_cast<std::size_t>(ahead)] >= 0) return false;
    const int left = goals_.left(k, ahead);
    if (left == 0 || left == kNever) return false;
    std::vector<int> moved = next;
    moved[static_cast<std::size_t>(k)] = ahead;
    return searcher_.stage_after(stage, moved) == stage;
  }

  // After a push onto `to` (holder_ and seen_after_ marked mark_ as it leaves them, the robot on `robot_cell`):
  // whether the places it closed off from the robot make a corral deadlock (CorralTest).
  bool corralled(const std::vector<int>& cells, int to, int robot_cell) {
    std::vector<int> seeds;
    for (int d = 0; d < kDirections; ++d) {
      const int c = lattice_.neighbour(to, d);
      if (c >= 0 && holder_[static_cast<std::size_t>(c)] < 0 && lattice_.robot_fits(c) && seen_after_[static_cast<std::size_t>(c)] != mark_) {
        seeds.push_back(c);
      }
    }
    return !seeds.empty() && CorralTest(lattice_, goals_, holder_, cells, seen_after_, mark_, corral_verdicts_).deadlocked(robot_cell, seeds);
  }

  // Body k of `from` pushed in direction d with the bodies in a line ahead of it, end to end, as many
  // places as it takes to end the pushing: whether it does (its order is then steps()). A line only ends
  // an order: its first push closes the gaps between the bodies, which then stand short of their places
  // (PushLattice::line_shortfalls), so no later push could start from the lattice.
  bool finish_with_line(const Expansion& from, int k, int d) {
    const int at = cells_[static_cast<std::size_t>(k)];
    if (lattice_.first_stand(k, at, d, [&](int c) { return seen_[static_cast<std::size_t>(c)] == from.reach; }) < 0) return false;
    const std::vector<int> line = line_ahead(lattice_, cells_, holder_, k, d);
    if (!lattice_.line_shortfalls(line, cells_, d)) return false;
    if (!std::all_of(line.begin(), line.end(), [&](int j) { return lattice_.can_push(j, d); })) return false;
    const std::vector<int> ahead(line.begin() + 1, line.end());
    std::vector<int> cells = cells_;
    std::vector<PushStep> run;
    while (true) {
      const int before = cells[static_cast<std::size_t>(k)];
      for (int j : line) {
        const int to = lattice_.neighbour(cells[static_cast<std::size_t>(j)], d);
        if (to < 0 || !lattice_.body_fits(j, to)) return false;
        cells[static_cast<std::size_t>(j)] = to;
      }
      // holder_ holds the arrangement before the line's first push: no body off the line may stand where
      // one of the line moves to.
      bool runs_into = false;
      for (int j : line) {
        lattice_.for_each_cover(j, cells[static_cast<std::size_t>(j)], [&](int c) {
          const int held = holder_[static_cast<std::size_t>(c)];
          runs_into |= held >= 0 && std::find(line.begin(), line.end(), held) == line.end();
        });
      }
      if (runs_into) return false;
      const int stage = searcher_.stage_after(from.stage, cells);
      if (stages_.distance(stage) < 0 || stages_.dead(stages_.automaton_state_of(stage))) return false;
      run.push_back({k, d, before, cells[static_cast<std::size_t>(k)], ahead});
      if (searcher_.ends_pushing(stage)) break;
    }
    steps_ = steps_to(store_.settled_met(from.settled));
    steps_.insert(steps_.end(), run.begin(), run.end());
    return true;
  }

  const PushLattice& lattice_;
  const planning::StageGraph& stages_;
  const PushSearcher& searcher_;
  const PushSearcher::Goals& goals_;
  double weight_;
  std::vector<int> holder_;      // per place, the body on it or -1
  std::vector<int> seen_;        // the robot's reach before a push (marks)
  std::vector<int> seen_after_;  // and after it
  std::vector<int> queue_;
  int mark_ = 0;
  CorralTest::Verdicts corral_verdicts_;
  ArrangementStore store_;
  std::vector<int> cells_;  // the places of the arrangement being settled
  // Open arrangements, in a deque: it grows without copying what it holds (a vector of tens of millions
  // copied whole as it grew held the search past its deadline).
  std::priority_queue<Open, std::deque<Open>, std::greater<>> open_;
  std::vector<PushStep> steps_;  // the order found
  // Goal rooms (goal_room.h): per lattice body, its rooms or nullptr; the ways of the goal macros'
  // arrangements, which a place and a direction do not tell, and what they hold.
  static constexpr std::size_t kMacroEntryBytes = 64;  // a map entry and a vector, besides the steps
  // A corral verdict: a map entry, its bucket and its key of up to 2 * kMaxCorralBodies + 1 places.
  static constexpr std::size_t kVerdictBytes = 128;
  std::vector<std::unique_ptr<GoalRooms>> rooms_;
  std::vector<const GoalRooms*> rooms_of_;
  std::unordered_map<int, std::vector<PushStep>> macro_runs_;
  std::size_t macro_bytes_ = 0;
};

PushSearch PushSearcher::search(int stage, const std::vector<int>& cells, int robot_cell, const base::Deadline& deadline,
                                SearchBudget budget, double weight) const {
  PushSearch result;
  const Goals goals = goals_from(stage, deadline);
  result.outcome = "no order of pushes";
  for (std::size_t k = 0; k < cells.size(); ++k) {
    if (goals.left(static_cast<int>(k), cells[k]) == kNever) return result;
  }
  if (ends_pushing(stage)) {
    result.found = true;
    result.outcome = "found";
    return result;
  }
  ArrangementSearch search(lattice_, stages_, *this, goals, weight, cells);
  search.start(robot_cell, stage, cells);
  while (!search.exhausted()) {
    if (++result.settled > budget.arrangements) {
      result.outcome = "search limit";
      return result;
    }
    if (search.bytes() > budget.bytes) {
      result.outcome = "memory limit";
      return result;
    }
    // Every settle: one of 16 boxes walks the robot's places some 60 times, and 256 of them took 0.7 s.
    deadline.check();
    if (search.settle()) {
      result.steps = search.steps();
      result.found = true;
      result.outcome = "found";
      return result;
    }
  }
  return result;
}

}  // namespace physltl::planners::knowledge::lookahead
