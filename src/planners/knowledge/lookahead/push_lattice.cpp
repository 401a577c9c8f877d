#include "push_lattice.h"

#include "physltl/knowledge/kappa.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace physltl::planners::knowledge::lookahead {
namespace {

constexpr double kTouch = 1e-6;  // m: touching a wall is not overlapping it
constexpr double kAlongAxis = 0.9;  // cosine: a face's push counts as a lattice direction
// Bodies and walls share a grid when their sides, and the bodies' with half the gap round them, lie a
// whole number of cells apart to this share of a cell; an outline covers its places when it reaches
// this far past none of them.
constexpr double kWholeCells = 0.02;
constexpr double kCoverTolerance = 1e-6;  // m
constexpr int kPlacesBetweenChecks = 4096;  // of the deadline: a fraction of a millisecond of work

bool square(double yaw) {
  const double quarter = std::numbers::pi / 2;
  return std::abs(std::remainder(yaw, quarter)) <= kSquareYaw;
}

}  // namespace

std::optional<PushLattice> PushLattice::build(const scenario::World& world, const physltl::knowledge::AbstractKnowledge& knowledge,
                                              const physltl::knowledge::Labelling& labelling, const base::Deadline& deadline,
                                              std::string& why_not) {
  PushLattice lattice;
  if (labelling.named_parts().empty()) {
    why_not = "the task names no body";
    return std::nullopt;
  }
  std::vector<geometry::Footprint> walls;
  for (const auto& f : knowledge.fixed_bodies) walls.push_back(f.footprint);
  if (!lattice.take_bodies(knowledge, walls, why_not)) return std::nullopt;
  const int anchor = labelling.named_parts().front().bodies.front();
  if (knowledge.movable_bodies[static_cast<std::size_t>(anchor)].body_class == physltl::knowledge::BodyClass::kFixed) {
    why_not = knowledge.movable_bodies[static_cast<std::size_t>(anchor)].name + " is too heavy to push";
    return std::nullopt;
  }
  for (const physltl::knowledge::Labelling::NamedPart& part : labelling.named_parts()) {
    for (int b : part.bodies) {
      // A group's place is all its bodies' together: one the lattice leaves out would be left out of it.
      if (part.bodies.size() > 1 && knowledge.movable_bodies[static_cast<std::size_t>(b)].body_class == physltl::knowledge::BodyClass::kFixed) {
        why_not = knowledge.movable_bodies[static_cast<std::size_t>(b)].name + " of " + part.name + " is too heavy to push";
        return std::nullopt;
      }
    }
  }
  lattice.push_force_ = knowledge.robot.push_force;
  // Unit bodies: the anchor's centre is a place; on a grid, the centre of the cell at its lower left.
  const geometry::Footprint& anchor_body = knowledge.movable_bodies[static_cast<std::size_t>(anchor)].footprint;
  const geometry::Vec2 first_place =
      lattice.unit_bodies_ ? anchor_body.pose.position
                           : geometry::bounds(anchor_body.shape, anchor_body.pose).min + geometry::Vec2::Constant((lattice.step_ - kLatticeGap) / 2);
  lattice.anchor_at(first_place, knowledge.workspace);
  std::vector<geometry::Rect> wall_bounds;
  for (const geometry::Footprint& w : walls) wall_bounds.push_back(geometry::bounds(w.shape, w.pose));
  double reach = knowledge.robot.radius;
  for (int b : lattice.bodies_) reach = std::max(reach, knowledge.movable_bodies[static_cast<std::size_t>(b)].footprint.shape.bound_radius());
  const Walls bucketed{std::move(walls), geometry::RectGrid(wall_bounds, reach + kTouch)};
  lattice.mark_robot_places(bucketed, knowledge.workspace, knowledge.robot.radius, deadline);
  // The region of each place, the same for every unit body (a larger body's centre is off its place).
  const physltl::knowledge::RegionMap regions(world);
  std::vector<int> region_of(lattice.unit_bodies_ ? static_cast<std::size_t>(lattice.cells()) : 0);
  for (std::size_t c = 0; c < region_of.size(); ++c) region_of[c] = regions.at(lattice.centre(static_cast<int>(c)));
  for (std::size_t k = 0; k < lattice.bodies_.size(); ++k) {
    if (!lattice.take_cover(k, knowledge)) {
      why_not = knowledge.movable_bodies[static_cast<std::size_t>(lattice.bodies_[k])].name + " does not cover whole places of the grid";
      return std::nullopt;
    }
    if (!lattice.add_body(k, regions, region_of, knowledge, labelling, bucketed, deadline, why_not)) return std::nullopt;
  }
  return lattice;
}

bool PushLattice::take_bodies(const physltl::knowledge::AbstractKnowledge& knowledge, std::vector<geometry::Footprint>& walls,
                              std::string& why_not) {
  double largest_side = 0.0, smallest_side = std::numeric_limits<double>::infinity();
  bool boxes = true;
  for (std::size_t b = 0; b < knowledge.movable_bodies.size(); ++b) {
    const auto& body = knowledge.movable_bodies[b];
    if (body.body_class == physltl::knowledge::BodyClass::kFixed) {
      walls.push_back(body.footprint);
      continue;
    }
    const geometry::Shape& shape = body.footprint.shape;
    if (shape.kind() == geometry::Shape::Kind::kCircle || !square(body.footprint.pose.yaw)) {
      why_not = body.name + " is not a box or a polygon standing square";
      return false;
    }
    boxes &= shape.is_box();
    // A box's sides as authored (its bounds' differ in the last bit).
    const geometry::Vec2 extent = shape.is_box() ? geometry::Vec2(2 * shape.half_extents()) : geometry::bounds(shape, body.footprint.pose).size();
    largest_side = std::max(largest_side, extent.maxCoeff());
    smallest_side = std::min(smallest_side, extent.minCoeff());
    bodies_.push_back(static_cast<int>(b));
    start_yaw_.push_back(body.footprint.pose.yaw);
  }
  if (take_grid(knowledge, smallest_side)) {
    if (unit_bodies_) step_ = largest_side + kLatticeGap;  // the same step, to the bit, as bodies off a grid get
    return true;
  }
  // Off any common grid: boxes, each on a place of the largest box's size.
  if (!boxes) {
    why_not = "its bodies and walls stand on no common grid of cells as wide as the robot";
    return false;
  }
  step_ = largest_side + kLatticeGap;
  return true;
}

bool PushLattice::take_grid(const physltl::knowledge::AbstractKnowledge& knowledge, double smallest_side) {
  if (bodies_.empty()) return false;
  // Lengths measured from the lower left of the first body's first cell (its bounds less half the gap).
  const geometry::Footprint& first = knowledge.movable_bodies[static_cast<std::size_t>(bodies_.front())].footprint;
  const geometry::Vec2 origin = geometry::bounds(first.shape, first.pose).min - geometry::Vec2::Constant(kLatticeGap / 2);
  std::vector<double> lengths;
  const auto add_rect = [&](const geometry::Rect& r, double grown) {
    for (const geometry::Vec2& corner : {r.min, r.max}) {
      const geometry::Vec2 from = corner - origin + geometry::Vec2::Constant(corner == r.min ? -grown : grown);
      lengths.insert(lengths.end(), {from.x(), from.y()});
    }
  };
  // Movable bodies (those too heavy to push too) stand half the gap inside their cells; walls fill theirs.
  for (const auto& body : knowledge.movable_bodies) add_rect(geometry::bounds(body.footprint.shape, body.footprint.pose), kLatticeGap / 2);
  for (const auto& wall : knowledge.fixed_bodies) add_rect(wall.bounds, 0.0);
  const auto whole = [&](double cell) {
    return std::all_of(lengths.begin(), lengths.end(), [&](double l) { return std::abs(l / cell - std::round(l / cell)) <= kWholeCells; });
  };
  // The largest cell, a whole share of the smallest body's side and the gap, that the robot fits in.
  const double robot_width = 2 * knowledge.robot.radius;
  for (int share = 1; (smallest_side + kLatticeGap) / share >= robot_width; ++share) {
    const double cell = (smallest_side + kLatticeGap) / share;
    if (!whole(cell)) continue;
    step_ = cell;
    unit_bodies_ = std::all_of(bodies_.begin(), bodies_.end(), [&](int b) {
      const geometry::Footprint& f = knowledge.movable_bodies[static_cast<std::size_t>(b)].footprint;
      return ((geometry::bounds(f.shape, f.pose).size().array() + kLatticeGap) / cell).maxCoeff() < 1 + kWholeCells;
    });
    return true;
  }
  return false;
}

bool PushLattice::take_cover(std::size_t k, const physltl::knowledge::AbstractKnowledge& knowledge) {
  const geometry::Footprint& f = knowledge.movable_bodies[static_cast<std::size_t>(bodies_[k])].footprint;
  if (unit_bodies_) {
    cover_.push_back({{0, 0}});
    centre_offset_.push_back(geometry::Vec2::Zero());
    return true;  // add_body says where it stands off its place
  }
  // The places whose centres the outline holds, from the lower left of its bounds.
  const geometry::Rect bounds = geometry::bounds(f.shape, f.pose);
  const int first = cell_at(bounds.min + geometry::Vec2::Constant((step_ - kLatticeGap) / 2));
  if (first < 0) return false;
  std::vector<int> covered;
  const geometry::Vec2 cells = (bounds.size() + geometry::Vec2::Constant(kLatticeGap)) / step_;
  for (int row = 0; row < static_cast<int>(std::lround(cells.y())); ++row) {
    for (int column = 0; column < static_cast<int>(std::lround(cells.x())); ++column) {
      const int c = shifted(first, {column, row});
      if (c >= 0 && geometry::contains(f.shape, f.pose, centre(c))) covered.push_back(c);
    }
  }
  if (covered.empty()) return false;
  // Sides along the axes only, and every corner of the outline within one of the places: the outline is
  // then those places, less the gap (a slanted side could cut a place it does not cover).
  const double half = step_ / 2 + kCoverTolerance;
  const geometry::Polygon outline = f.shape.is_box() ? geometry::Polygon{} : geometry::to_world(f.pose, f.shape.outline());
  for (std::size_t i = 0; i < outline.vertices.size(); ++i) {
    const geometry::Vec2 side = outline.vertices[(i + 1) % outline.vertices.size()] - outline.vertices[i];
    if (std::min(std::abs(side.x()), std::abs(side.y())) > kCoverTolerance) return false;
  }
  for (const geometry::Polygon& part : geometry::convex_parts_at(f.shape, f.pose, geometry::CircleAs::kInscribed)) {
    for (const geometry::Vec2& corner : part.vertices) {
      const bool inside = std::any_of(covered.begin(), covered.end(), [&](int c) {
        return ((corner - centre(c)).cwiseAbs().array() <= half).all();
      });
      if (!inside) return false;
    }
  }
  const int anchor = *std::min_element(covered.begin(), covered.end());
  auto& offsets = cover_.emplace_back();
  for (int c : covered) {
    offsets.push_back({places_.column_of(static_cast<std::size_t>(c)) - places_.column_of(static_cast<std::size_t>(anchor)),
                       places_.row_of(static_cast<std::size_t>(c)) - places_.row_of(static_cast<std::size_t>(anchor))});
  }
  centre_offset_.push_back(f.pose.position - centre(anchor));
  add_places_behind(offsets);
  return true;
}

void PushLattice::add_places_behind(const std::vector<std::array<int, 2>>& cover) {
  auto& behind = behind_.emplace_back();
  const geometry::Vec2 middle = centre_offset_.back() / step_;  // in places, from the anchor
  for (int d = 0; d < kDirections; ++d) {
    // By their distance from the centre line in millionths of a place: equal ones stay in cover order.
    std::vector<std::pair<long, std::array<int, 2>>> places;
    for (const std::array<int, 2>& offset : cover) {
      const std::array<int, 2> back{offset[0] - kDx[d], offset[1] - kDy[d]};
      if (std::find(cover.begin(), cover.end(), back) != cover.end()) continue;
      const double off = std::abs(geometry::cross(geometry::Vec2(back[0], back[1]) - middle, geometry::Vec2(kDx[d], kDy[d])));
      places.push_back({std::lround(off * 1e6), back});
    }
    std::stable_sort(places.begin(), places.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& [off, back] : places) behind[static_cast<std::size_t>(d)].push_back(back);
  }
}

int PushLattice::shifted(int cell, const std::array<int, 2>& offset) const {
  const int column = places_.column_of(static_cast<std::size_t>(cell)) + offset[0];
  const int row = places_.row_of(static_cast<std::size_t>(cell)) + offset[1];
  return places_.contains(column, row) ? static_cast<int>(places_.index(column, row)) : -1;
}

void PushLattice::anchor_at(const geometry::Vec2& a, const geometry::Rect& ws) {
  const double s = step_;
  origin_ = {a.x() - std::floor((a.x() - ws.min.x()) / s) * s, a.y() - std::floor((a.y() - ws.min.y()) / s) * s};
  places_ = geometry::UniformGrid(origin_, s, static_cast<int>(std::floor((ws.max.x() - origin_.x()) / s)) + 1,
                                  static_cast<int>(std::floor((ws.max.y() - origin_.y()) / s)) + 1);
  // The search asks for neighbours in its innermost loops (the robot's walks): looked up, not computed.
  neighbours_.resize(static_cast<std::size_t>(cells()) * kDirections);
  for (std::size_t c = 0; c < static_cast<std::size_t>(cells()); ++c) {
    for (int d = 0; d < kDirections; ++d) neighbours_[c * kDirections + static_cast<std::size_t>(d)] = static_cast<int>(places_.neighbour(c, kDx[d], kDy[d]));
  }
}

void PushLattice::mark_robot_places(const Walls& walls, const geometry::Rect& ws, double r, const base::Deadline& deadline) {
  const auto disc_free = [&](const geometry::Vec2& p) {
    if (p.x() - r < ws.min.x() || p.y() - r < ws.min.y() || p.x() + r > ws.max.x() || p.y() + r > ws.max.y()) return false;
    const std::span<const int> near = walls.near.near(p);
    return std::none_of(near.begin(), near.end(), [&](int i) {
      const geometry::Footprint& w = walls.footprints[static_cast<std::size_t>(i)];
      return geometry::overlap(w.shape, w.pose, p, r, kTouch);
    });
  };
  const int n = cells();
  robot_free_.resize(static_cast<std::size_t>(n));
  for (int c = 0; c < n; ++c) {
    if (c % kPlacesBetweenChecks == 0) deadline.check();
    robot_free_[static_cast<std::size_t>(c)] = disc_free(centre(c));
  }
  robot_passes_.assign(static_cast<std::size_t>(n) * kDirections, false);
  for (int c = 0; c < n; ++c) {
    if (c % kPlacesBetweenChecks == 0) deadline.check();
    for (int d = 0; d < kDirections; ++d) {
      const int next = neighbour(c, d);
      robot_passes_[static_cast<std::size_t>(c) * kDirections + static_cast<std::size_t>(d)] =
          next >= 0 && robot_fits(c) && robot_fits(next) && disc_free(0.5 * (centre(c) + centre(next)));
    }
  }
}

bool PushLattice::add_body(std::size_t k, const physltl::knowledge::RegionMap& regions, const std::vector<int>& region_of,
                           const physltl::knowledge::AbstractKnowledge& knowledge,
                           const physltl::knowledge::Labelling& labelling, const Walls& walls, const base::Deadline& deadline,
                           std::string& why_not) {
  const int b = bodies_[k];
  const auto& body = knowledge.movable_bodies[static_cast<std::size_t>(b)];
  const int at = body_cell(static_cast<int>(k), body.footprint.pose.position);
  if (at < 0 || (body_centre(static_cast<int>(k), at) - body.footprint.pose.position).norm() > kSnapShare * step_) {
    why_not = body.name + " stands between the lattice's places (step " + std::to_string(step_).substr(0, 4) + " m)";
    return false;
  }
  const int n = cells();
  std::vector<bool> fits(static_cast<std::size_t>(n));
  const std::size_t cover = cover_[k].size();
  for (int c = 0; c < n; ++c) {
    if (c % kPlacesBetweenChecks == 0) deadline.check();
    const geometry::Pose2 pose{body_centre(static_cast<int>(k), c), body.footprint.pose.yaw};
    std::size_t covered = 0;
    for_each_cover(static_cast<int>(k), c, [&](int) { ++covered; });
    const std::span<const int> near = walls.near.near(pose.position);
    fits[static_cast<std::size_t>(c)] =
        covered == cover && geometry::inside(body.footprint.shape, pose, knowledge.workspace, kTouch) &&
        std::none_of(near.begin(), near.end(), [&](int i) {
          const geometry::Footprint& w = walls.footprints[static_cast<std::size_t>(i)];
          return geometry::overlap(body.footprint.shape, pose, w.shape, w.pose, kTouch);
        });
  }
  body_free_.push_back(std::move(fits));
  std::vector<bool> pushable(kDirections, false);
  for (const auto& m : body.mregions) {
    const geometry::Vec2 push = physltl::knowledge::push_direction(m, body.footprint.pose);
    for (int d = 0; d < kDirections; ++d) {
      if (push.dot(geometry::Vec2(kDx[d], kDy[d])) >= kAlongAxis) pushable[static_cast<std::size_t>(d)] = true;
    }
  }
  pushable_.push_back(std::move(pushable));
  friction_force_.push_back(body.floor_friction_force);
  const geometry::Rect extent = geometry::bounds(body.footprint.shape, body.footprint.pose);
  half_along_.push_back({extent.size().x() / 2, extent.size().y() / 2});
  const int named = labelling.part_of(b);
  named_.push_back(named);
  std::vector<int> place(static_cast<std::size_t>(n), 0);
  if (named >= 0) {
    const physltl::knowledge::Labelling::NamedPart& part = labelling.named_parts()[static_cast<std::size_t>(named)];
    for (int c = 0; c < n; ++c) {
      // A unit body's centre is on its place; a larger one's, where its offset puts it.
      const int region = unit_bodies_ ? region_of[static_cast<std::size_t>(c)] : regions.at(body_centre(static_cast<int>(k), c));
      place[static_cast<std::size_t>(c)] = part.place_of_region(region);
    }
  }
  place_.push_back(std::move(place));
  return true;
}

std::optional<std::vector<double>> PushLattice::line_shortfalls(const std::vector<int>& line, const std::vector<int>& cells, int d) const {
  double held = 0.0;
  for (int k : line) held += friction_force_[static_cast<std::size_t>(k)];
  if (held >= push_force_) return std::nullopt;
  std::vector<double> shortfalls;
  if (!unit_bodies_) {
    // On a grid every gap is kLatticeGap: a body ends as many gaps short as there are contacts between
    // it and the pushed one (its level: one more than the body ahead of which it stands).
    std::vector<int> level(line.size(), -1);
    level[0] = 0;
    for (std::size_t i = 0; i < line.size(); ++i) {
      if (level[i] < 0) return std::nullopt;  // it touches no body before it
      for_each_cover(line[i], cells[static_cast<std::size_t>(line[i])], [&](int c) {
        const int ahead = neighbour(c, d);
        for (std::size_t j = i + 1; j < line.size() && ahead >= 0; ++j) {
          bool covers = false;
          for_each_cover(line[j], cells[static_cast<std::size_t>(line[j])], [&](int p) { covers |= p == ahead; });
          if (covers && level[j] < 0) level[j] = level[i] + 1;
        }
      });
    }
    for (std::size_t i = 1; i < line.size(); ++i) {
      const double shortfall = level[i] * kLatticeGap;
      if (shortfall >= step_ / 2) return std::nullopt;
      shortfalls.push_back(shortfall);
    }
    return shortfalls;
  }
  double shortfall = 0.0;
  for (std::size_t i = 1; i < line.size(); ++i) {
    shortfall += step_ - half_along(line[i - 1], d) - half_along(line[i], d);
    if (shortfall >= step_ / 2) return std::nullopt;
    shortfalls.push_back(shortfall);
  }
  return shortfalls;
}

geometry::Vec2 PushLattice::centre(int cell) const {
  const auto at = static_cast<std::size_t>(cell);
  return origin_ + step_ * geometry::Vec2(places_.column_of(at), places_.row_of(at));
}

int PushLattice::cell_at(const geometry::Vec2& p) const {
  // The nearest place: the lattice's places are its grid's cell corners, not their centres.
  const int column = static_cast<int>(std::lround((p.x() - origin_.x()) / step_));
  const int row = static_cast<int>(std::lround((p.y() - origin_.y()) / step_));
  return places_.contains(column, row) ? static_cast<int>(places_.index(column, row)) : -1;
}

std::optional<std::vector<int>> PushLattice::arrangement(const scenario::EnvironmentState& state) const {
  std::vector<int> cells;
  for (std::size_t k = 0; k < bodies_.size(); ++k) {
    const geometry::Pose2& pose = state.movable_poses[static_cast<std::size_t>(bodies_[k])];
    const int at = body_cell(static_cast<int>(k), pose.position);
    if (at < 0 || (body_centre(static_cast<int>(k), at) - pose.position).norm() > kSnapShare * step_) return std::nullopt;
    // A unit box may stand turned by quarter turns; a body of several places covers them turned as it started.
    const bool turned_as_before =
        unit_bodies_ ? square(pose.yaw) : std::abs(std::remainder(pose.yaw - start_yaw_[k], 2 * std::numbers::pi)) <= kSquareYaw;
    if (!turned_as_before) return std::nullopt;
    cells.push_back(at);
  }
  return cells;
}

int PushLattice::robot_cell(const geometry::Vec2& p) const {
  const int at = cell_at(p);
  if (at >= 0 && robot_fits(at)) return at;
  int best = -1;
  double nearest = step_;
  for (int dx = -1; dx <= 1; ++dx) {
    for (int dy = -1; dy <= 1; ++dy) {
      const int c = cell_at(p + step_ * geometry::Vec2(dx, dy));
      if (c < 0 || !robot_fits(c)) continue;
      const double d = (centre(c) - p).norm();
      if (d < nearest) nearest = d, best = c;
    }
  }
  return best;
}

}  // namespace physltl::planners::knowledge::lookahead
