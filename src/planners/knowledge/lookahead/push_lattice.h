#pragma once
// The look-ahead's lattice: places one step apart where the pushable bodies may stand, anchored at a
// named body's start, and what each place allows: a body there touches no wall, the robot there touches
// none, the robot may walk to the next place. Two ways to lay it:
// - bodies of one size (boxes, as Sokoban has them): the step is the bodies' largest side plus
//   kLatticeGap, so bodies on neighbouring places do not touch and a push of one step leaves the robot in
//   the place the body left; each body covers one place.
// - bodies of any sizes and shapes on one grid with the walls (bars, blocks, L and T shapes made of
//   cells, as grid puzzles have them): the step is the common cell, the largest whole share of the
//   smallest body's side and kLatticeGap that the robot fits in and that every body's and wall's sides
//   lie on, and a body covers the places its outline covers. Its place is the first of them (its
//   anchor); a push moves it one place, the robot behind the face it pushes, nearest the body's centre.
//   Bodies of one size on the walls' grid make the first way (Sokoban's levels).

#include "physltl/base/deadline.h"
#include "physltl/geometry/rect_grid.h"
#include "physltl/geometry/uniform_grid.h"
#include "physltl/knowledge/abstract_knowledge.h"
#include "physltl/knowledge/labelling.h"
#include "physltl/scenario/state.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace physltl::planners::knowledge::lookahead {

inline constexpr double kLatticeGap = 0.10;  // m between neighbouring bodies' sides
// A body counts as standing on a place when its centre is this share of a step from it, and square when
// its yaw is this close to a quarter turn.
inline constexpr double kSnapShare = 0.25;
inline constexpr double kSquareYaw = 0.2;  // rad

// Directions: +x, -x, +y, -y.
inline constexpr int kDirections = 4;
inline constexpr int kDx[kDirections] = {1, -1, 0, 0};
inline constexpr int kDy[kDirections] = {0, 0, 1, -1};
inline constexpr int opposite(int d) { return d ^ 1; }
inline constexpr int perpendicular(int d) { return d ^ 2; }  // a direction along the other axis

class PushLattice {
 public:
  // Nothing, with `why_not` said, when the World's pushable bodies do not stand on one lattice. A large
  // workspace has hundreds of thousands of places: checks `deadline` as it goes (DeadlineReached).
  static std::optional<PushLattice> build(const scenario::World& world, const physltl::knowledge::AbstractKnowledge& knowledge,
                                          const physltl::knowledge::Labelling& labelling, const base::Deadline& deadline,
                                          std::string& why_not);

  double step() const { return step_; }
  // Whether every body covers one place (the first way above): the search's deadlock rules, tunnels, goal
  // rooms and lines of bodies hold for such bodies only.
  bool unit_bodies() const { return unit_bodies_; }
  int cells() const { return static_cast<int>(places_.size()); }
  geometry::Vec2 centre(int cell) const;
  // The place nearest `p`, or -1 outside the lattice.
  int cell_at(const geometry::Vec2& p) const;
  // The next place in direction `d`, or -1 past the lattice's edge.
  int neighbour(int cell, int d) const { return neighbours_[static_cast<std::size_t>(cell) * kDirections + static_cast<std::size_t>(d)]; }

  // The bodies on the lattice: World::movable_bodies indices of the pushable ones.
  const std::vector<int>& bodies() const { return bodies_; }
  bool body_fits(int k, int cell) const { return body_free_[static_cast<std::size_t>(k)][static_cast<std::size_t>(cell)]; }
  // Where lattice body k's centre is with its place on `cell`, and the place of body k whose centre is at `p`.
  geometry::Vec2 body_centre(int k, int cell) const { return centre(cell) + centre_offset_[static_cast<std::size_t>(k)]; }
  int body_cell(int k, const geometry::Vec2& p) const { return cell_at(p - centre_offset_[static_cast<std::size_t>(k)]); }
  // The places lattice body k covers with its place on `cell`, each passed to `f` (one for a unit body);
  // those off the lattice are left out (the body does not fit there).
  template <class F>
  void for_each_cover(int k, int cell, F&& f) const {
    if (unit_bodies_) return f(cell);  // the search's innermost loops: no column and row to work out
    for (const std::array<int, 2>& offset : cover_[static_cast<std::size_t>(k)]) {
      const int c = shifted(cell, offset);
      if (c >= 0) f(c);
    }
  }
  // The place the robot pushes lattice body k on `cell` in direction d from: of the places behind the
  // face it pushes, the first that `usable` accepts, nearest the line through the body's centre first
  // (a push there turns the body least); -1 when none does. For a unit body, the place behind it.
  template <class F>
  int first_stand(int k, int cell, int d, F&& usable) const {
    if (unit_bodies_) {
      const int stand = neighbour(cell, opposite(d));
      return stand >= 0 && usable(stand) ? stand : -1;
    }
    for (const std::array<int, 2>& offset : behind_[static_cast<std::size_t>(k)][static_cast<std::size_t>(d)]) {
      const int stand = shifted(cell, offset);
      if (stand >= 0 && usable(stand)) return stand;
    }
    return -1;
  }
  bool can_push(int k, int d) const { return pushable_[static_cast<std::size_t>(k)][static_cast<std::size_t>(d)]; }
  // Half lattice body k's extent along direction d.
  double half_along(int k, int d) const { return half_along_[static_cast<std::size_t>(k)][static_cast<std::size_t>(d / 2)]; }
  // Whether the robot's drive moves the bodies `line` (lattice bodies on `cells`, end to end, the robot's
  // first; bodies of several places: each the first ahead of one before it, each touching one before it)
  // at once in direction d, and how far short of their next places the bodies ahead of the first end, in
  // line order: pushed one place on, the first closes the gaps before the others move. Nothing when the
  // floor friction of them all holds the drive back, or a body would end nearer another place than its own.
  std::optional<std::vector<double>> line_shortfalls(const std::vector<int>& line, const std::vector<int>& cells, int d) const;
  // Labelling::named_parts index of lattice body k, or -1 when the task does not name it.
  int named(int k) const { return named_[static_cast<std::size_t>(k)]; }
  // The place (labelling.h) of named lattice body k at `cell`.
  int place(int k, int cell) const { return place_[static_cast<std::size_t>(k)][static_cast<std::size_t>(cell)]; }
  bool robot_fits(int cell) const { return robot_free_[static_cast<std::size_t>(cell)]; }
  bool robot_passes(int cell, int d) const { return robot_passes_[static_cast<std::size_t>(cell) * kDirections + static_cast<std::size_t>(d)]; }

  // Each lattice body's place in `state`, or nothing when one stands off its place or is turned.
  std::optional<std::vector<int>> arrangement(const scenario::EnvironmentState& state) const;
  // The robot's place: the nearest place it fits in, within one step of `p`; -1 when none.
  int robot_cell(const geometry::Vec2& p) const;

 private:
  // The place `offset` (columns, rows) from `cell`, or -1 off the lattice.
  int shifted(int cell, const std::array<int, 2>& offset) const;
  // The step when the bodies and the walls stand on one grid of cells the robot fits in: the largest whole
  // share of the smallest body's side and the gap; false when there is none.
  bool take_grid(const physltl::knowledge::AbstractKnowledge& knowledge, double smallest_side);
  // Lattice body k's cover, anchor and centre offset from where it stands; false when its outline is not
  // the places it covers.
  bool take_cover(std::size_t k, const physltl::knowledge::AbstractKnowledge& knowledge);
  // behind_ of the body just covered, whose places are `cover`.
  void add_places_behind(const std::vector<std::array<int, 2>>& cover);
  PushLattice() = default;
  // The pushable bodies (fixed ones join `walls`) and the step; false, with why_not, when one is neither a
  // box nor a polygon standing square, or polygons stand on no grid with the walls.
  bool take_bodies(const physltl::knowledge::AbstractKnowledge& knowledge, std::vector<geometry::Footprint>& walls, std::string& why_not);
  // The places: one at `anchor`, the others a step apart from it across the workspace.
  void anchor_at(const geometry::Vec2& anchor, const geometry::Rect& workspace);
  // The walls (fixed bodies and those too heavy to push), bucketed: a place asks only the walls near it.
  struct Walls {
    std::vector<geometry::Footprint> footprints;
    geometry::RectGrid near;  // within reach of the robot and of every lattice body about its centre
  };
  void mark_robot_places(const Walls& walls, const geometry::Rect& workspace, double robot_radius, const base::Deadline& deadline);
  // Where lattice body k fits, how it may be pushed, its places for the task (`region_of`: each place's
  // World region, -1 for none, where a unit body's centre is; `regions` for a larger body's centre);
  // false, with why_not, when it stands between places.
  bool add_body(std::size_t k, const physltl::knowledge::RegionMap& regions, const std::vector<int>& region_of,
                const physltl::knowledge::AbstractKnowledge& knowledge,
                const physltl::knowledge::Labelling& labelling, const Walls& walls, const base::Deadline& deadline,
                std::string& why_not);

  double step_ = 0.0;
  geometry::Vec2 origin_ = geometry::Vec2::Zero();  // the centre of place 0
  geometry::UniformGrid places_;  // row by row: a place's column and row
  std::vector<int> bodies_;
  std::vector<int> named_;
  std::vector<int> neighbours_;                // per place and direction: neighbour()
  std::vector<std::vector<bool>> body_free_;   // per lattice body, per place
  std::vector<std::vector<bool>> pushable_;    // per lattice body, per direction
  std::vector<std::vector<int>> place_;        // per lattice body, per place
  std::vector<double> friction_force_;         // per lattice body: N to start it sliding
  std::vector<std::array<double, 2>> half_along_;  // per lattice body: half its extent along x and y
  bool unit_bodies_ = true;
  std::vector<std::vector<std::array<int, 2>>> cover_;  // per lattice body: its places' offsets from its anchor
  // Per lattice body, per direction: the offsets of the places behind the face pushed that way, nearest the
  // line through its centre first.
  std::vector<std::array<std::vector<std::array<int, 2>>, kDirections>> behind_;
  std::vector<geometry::Vec2> centre_offset_;          // per lattice body: its centre from its anchor's
  std::vector<double> start_yaw_;                      // per lattice body
  double push_force_ = 0.0;                    // N: the robot's drive
  std::vector<bool> robot_free_;
  std::vector<bool> robot_passes_;             // per place and direction
};

}  // namespace physltl::planners::knowledge::lookahead
