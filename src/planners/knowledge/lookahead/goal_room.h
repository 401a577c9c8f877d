#pragma once
// Goal rooms, for the push search's goal macro (Junghanns and Schaeffer's): places the robot can only
// walk into through one place, the entrance, holding two or more of a body's goal places. A body pushed
// onto the entrance, into the room, may be pushed on at once along a way inside it to the deepest goal
// place still free (push_search.cpp), so that the search does not weigh every arrangement of boxes
// half-way into a room that is filled from the back.

#include "push_lattice.h"

#include <algorithm>
#include <functional>
#include <vector>

namespace physltl::planners::knowledge::lookahead {

// The most places a room may have: the macro's way is found by a search over the room's places, each
// step a walk of the robot through them.
inline constexpr int kMaxRoomPlaces = 100;

struct GoalRoom {
  int entrance = -1;
  std::vector<int> places;  // behind the entrance, in order
  std::vector<int> goals;   // its goal places, the farthest walk from the entrance first
  bool inside(int cell) const { return std::binary_search(places.begin(), places.end(), cell); }
  // The places lattice body k, pushed in direction d onto the entrance, passes on the fewest pushes
  // into the room and on through it (the robot walking between pushes through the room and the entrance,
  // round the places `held`) to the first of `goals` it can get to; empty when it can get to none.
  // `may_stand`: whether the body may stand on a place of the room (it fits, no body holds it, it can
  // still get where the task wants it from there).
  std::vector<int> way_in(const PushLattice& lattice, int k, int d, const std::function<bool(int)>& may_stand,
                          const std::function<bool(int)>& held) const;
};

class GoalRooms {
 public:
  // The rooms of a body whose goal places are `goal` (per lattice place), on the places the robot can
  // walk to from `root` (its start): a room is what a single place cuts off from `root`, of at most
  // kMaxRoomPlaces places.
  GoalRooms(const PushLattice& lattice, const std::vector<bool>& goal, int root);
  // The room a body pushed onto `cell` in direction d goes into, or nullptr.
  const GoalRoom* entered(int cell, int d) const {
    const int room = entered_[static_cast<std::size_t>(cell) * kDirections + static_cast<std::size_t>(d)];
    return room < 0 ? nullptr : &rooms_[static_cast<std::size_t>(room)];
  }
  std::size_t size() const { return rooms_.size(); }

 private:
  void add_room(const PushLattice& lattice, const std::vector<bool>& goal, int entrance, std::vector<int> places);

  std::vector<GoalRoom> rooms_;
  std::vector<int> entered_;  // per place and direction: the room, or -1
};

}  // namespace physltl::planners::knowledge::lookahead
