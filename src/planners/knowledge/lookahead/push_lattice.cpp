#include "push_lattice.h"

#include "physltl/knowledge/kappa.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace physltl::planning::lookahead {
namespace {

constexpr double kTouch = 1e-6;  // m: touching a wall is not overlapping it
constexpr double kAlongAxis = 0.9;  // cosine: a face's push counts as a lattice direction

bool square(double yaw) {
  const double quarter = std::numbers::pi / 2;
  return std::abs(std::remainder(yaw, quarter)) <= kSquareYaw;
}

}  // namespace

std::optional<PushLattice> PushLattice::build(const scenario::World& world, const knowledge::AbstractKnowledge& knowledge,
                                              const knowledge::Labelling& labelling, std::string& why_not) {
  PushLattice lattice;
  if (labelling.named_parts().empty()) {
    why_not = "the task names no body";
    return std::nullopt;
  }
  std::vector<geometry::Footprint> walls;
  for (const auto& f : knowledge.fixed_bodies) walls.push_back(f.footprint);
  if (!lattice.take_bodies(knowledge, walls, why_not)) return std::nullopt;
  const int anchor = labelling.named_parts().front().bodies.front();
  if (knowledge.movable_bodies[static_cast<std::size_t>(anchor)].body_class == knowledge::BodyClass::kFixed) {
    why_not = knowledge.movable_bodies[static_cast<std::size_t>(anchor)].name + " is too heavy to push";
    return std::nullopt;
  }
  for (const knowledge::Labelling::NamedPart& part : labelling.named_parts()) {
    for (int b : part.bodies) {
      // A group's place is all its bodies' together: one the lattice leaves out would be left out of it.
      if (part.bodies.size() > 1 && knowledge.movable_bodies[static_cast<std::size_t>(b)].body_class == knowledge::BodyClass::kFixed) {
        why_not = knowledge.movable_bodies[static_cast<std::size_t>(b)].name + " of " + part.name + " is too heavy to push";
        return std::nullopt;
      }
    }
  }
  lattice.push_force_ = knowledge.robot.push_force;
  lattice.anchor_at(knowledge.movable_bodies[static_cast<std::size_t>(anchor)].footprint.pose.position, knowledge.workspace);
  lattice.mark_robot_places(walls, knowledge.workspace, knowledge.robot.radius);
  // The region of each place, the same for every body.
  const knowledge::RegionMap regions(world);
  std::vector<int> region_of(static_cast<std::size_t>(lattice.cells()));
  for (int c = 0; c < lattice.cells(); ++c) region_of[static_cast<std::size_t>(c)] = regions.at(lattice.centre(c));
  for (std::size_t k = 0; k < lattice.bodies_.size(); ++k) {
    if (!lattice.add_body(k, region_of, knowledge, labelling, walls, why_not)) return std::nullopt;
  }
  return lattice;
}

bool PushLattice::take_bodies(const knowledge::AbstractKnowledge& knowledge, std::vector<geometry::Footprint>& walls,
                              std::string& why_not) {
  double largest_side = 0.0;
  for (std::size_t b = 0; b < knowledge.movable_bodies.size(); ++b) {
    const auto& body = knowledge.movable_bodies[b];
    if (body.body_class == knowledge::BodyClass::kFixed) {
      walls.push_back(body.footprint);
      continue;
    }
    if (!body.footprint.shape.is_box() || !square(body.footprint.pose.yaw)) {
      why_not = body.name + " is not a box standing square";
      return false;
    }
    largest_side = std::max(largest_side, 2 * body.footprint.shape.half_extents().maxCoeff());
    bodies_.push_back(static_cast<int>(b));
  }
  step_ = largest_side + kLatticeGap;
  return true;
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

void PushLattice::mark_robot_places(const std::vector<geometry::Footprint>& walls, const geometry::Rect& ws, double r) {
  const auto disc_free = [&](const geometry::Vec2& p) {
    if (p.x() - r < ws.min.x() || p.y() - r < ws.min.y() || p.x() + r > ws.max.x() || p.y() + r > ws.max.y()) return false;
    return std::none_of(walls.begin(), walls.end(),
                        [&](const geometry::Footprint& w) { return geometry::overlap(w.shape, w.pose, p, r, kTouch); });
  };
  const int n = cells();
  robot_free_.resize(static_cast<std::size_t>(n));
  for (int c = 0; c < n; ++c) robot_free_[static_cast<std::size_t>(c)] = disc_free(centre(c));
  robot_passes_.assign(static_cast<std::size_t>(n) * kDirections, false);
  for (int c = 0; c < n; ++c) {
    for (int d = 0; d < kDirections; ++d) {
      const int next = neighbour(c, d);
      robot_passes_[static_cast<std::size_t>(c) * kDirections + static_cast<std::size_t>(d)] =
          next >= 0 && robot_fits(c) && robot_fits(next) && disc_free(0.5 * (centre(c) + centre(next)));
    }
  }
}

bool PushLattice::add_body(std::size_t k, const std::vector<int>& region_of, const knowledge::AbstractKnowledge& knowledge,
                           const knowledge::Labelling& labelling, const std::vector<geometry::Footprint>& walls,
                           std::string& why_not) {
  const int b = bodies_[k];
  const auto& body = knowledge.movable_bodies[static_cast<std::size_t>(b)];
  const int at = cell_at(body.footprint.pose.position);
  if (at < 0 || (centre(at) - body.footprint.pose.position).norm() > kSnapShare * step_) {
    why_not = body.name + " stands between the lattice's places (step " + std::to_string(step_).substr(0, 4) + " m)";
    return false;
  }
  const int n = cells();
  std::vector<bool> fits(static_cast<std::size_t>(n));
  for (int c = 0; c < n; ++c) {
    const geometry::Pose2 pose{centre(c), body.footprint.pose.yaw};
    fits[static_cast<std::size_t>(c)] =
        geometry::inside(body.footprint.shape, pose, knowledge.workspace, kTouch) &&
        std::none_of(walls.begin(), walls.end(), [&](const geometry::Footprint& w) {
          return geometry::overlap(body.footprint.shape, pose, w.shape, w.pose, kTouch);
        });
  }
  body_free_.push_back(std::move(fits));
  std::vector<bool> pushable(kDirections, false);
  for (const auto& m : body.mregions) {
    const geometry::Vec2 push = knowledge::push_direction(m, body.footprint.pose);
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
    const knowledge::Labelling::NamedPart& part = labelling.named_parts()[static_cast<std::size_t>(named)];
    for (int c = 0; c < n; ++c) place[static_cast<std::size_t>(c)] = part.place_of_region(region_of[static_cast<std::size_t>(c)]);
  }
  place_.push_back(std::move(place));
  return true;
}

std::optional<std::vector<double>> PushLattice::line_shortfalls(const std::vector<int>& line, int d) const {
  double held = 0.0;
  for (int k : line) held += friction_force_[static_cast<std::size_t>(k)];
  if (held >= push_force_) return std::nullopt;
  std::vector<double> shortfalls;
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
  for (int b : bodies_) {
    const geometry::Pose2& pose = state.movable_poses[static_cast<std::size_t>(b)];
    const int at = cell_at(pose.position);
    if (at < 0 || (centre(at) - pose.position).norm() > kSnapShare * step_ || !square(pose.yaw)) return std::nullopt;
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

}  // namespace physltl::planning::lookahead
