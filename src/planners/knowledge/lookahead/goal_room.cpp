#include "goal_room.h"

#include <algorithm>
#include <map>

namespace physltl::planners::knowledge::lookahead {

GoalRooms::GoalRooms(const PushLattice& lattice, const std::vector<bool>& goal, int root)
    : entered_(static_cast<std::size_t>(lattice.cells()) * kDirections, -1) {
  if (root < 0) return;
  // Tarjan's cut places, depth first from `root` without recursion: a place's descendants are the
  // places found after it, as many as its subtree's size, and a child whose subtree reaches no place
  // found before its parent is cut off from `root` by the parent.
  const auto n = static_cast<std::size_t>(lattice.cells());
  std::vector<int> found(n, -1), low(n, 0), size(n, 1), goals(n, 0), order;
  struct Frame {
    int place, parent, direction;
  };
  std::vector<Frame> stack{{root, -1, 0}};
  found[static_cast<std::size_t>(root)] = 0;
  order.push_back(root);
  int root_children = 0;
  std::vector<int> rooms_behind_root;
  while (!stack.empty()) {
    Frame& frame = stack.back();
    const auto at = static_cast<std::size_t>(frame.place);
    if (frame.direction < kDirections) {
      const int d = frame.direction++;
      const int next = lattice.neighbour(frame.place, d);
      if (next < 0 || !lattice.robot_passes(frame.place, d) || !lattice.robot_fits(next)) continue;
      const auto to = static_cast<std::size_t>(next);
      if (found[to] >= 0) {
        if (next != frame.parent) low[at] = std::min(low[at], found[to]);
        continue;
      }
      found[to] = low[to] = static_cast<int>(order.size());
      order.push_back(next);
      if (frame.parent < 0) ++root_children;
      stack.push_back({next, frame.place, 0});  // `frame` is not used past here
      continue;
    }
    const Frame done = frame;
    stack.pop_back();
    goals[at] += goal[at] ? 1 : 0;
    if (done.parent < 0) continue;
    const auto parent = static_cast<std::size_t>(done.parent);
    low[parent] = std::min(low[parent], low[at]);
    size[parent] += size[at];
    goals[parent] += goals[at];
    if (low[at] < found[parent] || goals[at] < 2 || size[at] > kMaxRoomPlaces) continue;
    if (done.parent == root) {
      rooms_behind_root.push_back(done.place);  // a room only if the root cuts something else off too
      continue;
    }
    const auto first = order.begin() + found[at];
    add_room(lattice, goal, done.parent, {first, first + size[at]});
  }
  if (root_children < 2) return;
  for (int child : rooms_behind_root) {
    const auto first = order.begin() + found[static_cast<std::size_t>(child)];
    add_room(lattice, goal, root, {first, first + size[static_cast<std::size_t>(child)]});
  }
}

void GoalRooms::add_room(const PushLattice& lattice, const std::vector<bool>& goal, int entrance, std::vector<int> places) {
  GoalRoom room;
  room.entrance = entrance;
  std::sort(places.begin(), places.end());
  room.places = std::move(places);
  // The robot's walk from the entrance: the deepest goal places first, so that a room fills from the back.
  const auto slot = [&](int c) { return static_cast<std::size_t>(std::lower_bound(room.places.begin(), room.places.end(), c) - room.places.begin()); };
  std::vector<int> walked(room.places.size(), -1);
  std::vector<int> queue{entrance};
  for (std::size_t i = 0; i < queue.size(); ++i) {
    const int c = queue[i];
    const int here = c == entrance ? 0 : walked[slot(c)];
    for (int d = 0; d < kDirections; ++d) {
      const int next = lattice.neighbour(c, d);
      if (next < 0 || !lattice.robot_passes(c, d) || !room.inside(next) || walked[slot(next)] >= 0) continue;
      walked[slot(next)] = here + 1;
      queue.push_back(next);
    }
  }
  for (int c : room.places) {
    if (goal[static_cast<std::size_t>(c)]) room.goals.push_back(c);
  }
  std::sort(room.goals.begin(), room.goals.end(), [&](int a, int b) {
    const int wa = walked[slot(a)], wb = walked[slot(b)];
    return wa != wb ? wa > wb : a < b;
  });
  const auto index = static_cast<int>(rooms_.size());
  for (int d = 0; d < kDirections; ++d) {
    const int next = lattice.neighbour(entrance, d);
    if (next >= 0 && room.inside(next)) entered_[static_cast<std::size_t>(entrance) * kDirections + static_cast<std::size_t>(d)] = index;
  }
  rooms_.push_back(std::move(room));
}

std::vector<int> GoalRoom::way_in(const PushLattice& lattice, int k, int d, const std::function<bool(int)>& may_stand,
                                  const std::function<bool(int)>& held) const {
  const auto movable = [&](int c) { return c >= 0 && inside(c) && may_stand(c); };
  // A place of the room or the entrance as an index: the room's places in order, then the entrance.
  const auto slot = [&](int c) {
    return c == entrance ? places.size() : static_cast<std::size_t>(std::lower_bound(places.begin(), places.end(), c) - places.begin());
  };
  // Which of those the robot on `from` walks to, with the body on `body`.
  const auto walk = [&](int from, int body) {
    std::vector<bool> reach(places.size() + 1, false);
    if (from < 0 || from == body || held(from) || (from != entrance && !inside(from))) return reach;
    std::vector<int> queue{from};
    reach[slot(from)] = true;
    for (std::size_t i = 0; i < queue.size(); ++i) {
      for (int step = 0; step < kDirections; ++step) {
        const int next = lattice.neighbour(queue[i], step);
        if (next < 0 || next == body || !lattice.robot_passes(queue[i], step) || (next != entrance && !inside(next)) || held(next)) continue;
        if (reach[slot(next)]) continue;
        reach[slot(next)] = true;
        queue.push_back(next);
      }
    }
    return reach;
  };
  const int first = lattice.neighbour(entrance, d);
  if (!movable(first) || !lattice.can_push(k, d)) return {};
  // Breadth first over the body's place and the side the robot stands on, each state's state before it.
  using State = std::pair<int, int>;
  std::map<State, State> came_from{{{first, opposite(d)}, {entrance, -1}}};
  std::map<int, State> reached{{first, {first, opposite(d)}}};
  std::vector<State> queue{{first, opposite(d)}};
  for (std::size_t i = 0; i < queue.size(); ++i) {
    const auto [body, side] = queue[i];
    const std::vector<bool> reach = walk(lattice.neighbour(body, side), body);
    for (int push = 0; push < kDirections; ++push) {
      const int stand = lattice.neighbour(body, opposite(push));
      const int to = lattice.neighbour(body, push);
      if (stand < 0 || (stand != entrance && !inside(stand)) || !reach[slot(stand)] || !lattice.can_push(k, push) || !movable(to)) continue;
      if (!came_from.try_emplace({to, opposite(push)}, State{body, side}).second) continue;
      queue.push_back({to, opposite(push)});
      reached.try_emplace(to, State{to, opposite(push)});
    }
  }
  for (int goal : goals) {
    const auto found = reached.find(goal);
    if (found == reached.end()) continue;
    std::vector<int> way;
    for (State state = found->second; state.second >= 0; state = came_from.at(state)) way.push_back(state.first);
    std::reverse(way.begin(), way.end());
    return way;
  }
  return {};
}

}  // namespace physltl::planners::knowledge::lookahead
