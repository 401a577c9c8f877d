#include "physltl/knowledge/feasibility.h"

#include "obstacle.h"
#include "physltl/geometry/disc_field.h"
#include "physltl/geometry/free_space.h"
#include "physltl/ltl/object_atom.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>

namespace physltl::knowledge {
namespace {

using geometry::Vec2;

// Square cells covering the workspace (geometry/uniform_grid.h); a cell stands for its centre.
using Grid = geometry::UniformGrid;

// The footprints that block the robot: fixed bodies, and optionally the movable ones too heavy to push.
std::vector<geometry::Footprint> blocking_footprints(const AbstractKnowledge& k, bool with_unpushable_bodies) {
  std::vector<geometry::Footprint> footprints;
  for (const auto& f : k.fixed_bodies) footprints.push_back(f.footprint);
  if (with_unpushable_bodies) {
    for (const auto& m : k.movable_bodies) {
      if (m.body_class == BodyClass::kFixed) footprints.push_back(m.footprint);
    }
  }
  return footprints;
}

// Where a disc of `radius` can have its centre (cell centres tested exactly), and which of those cells
// it reaches from the robot's start by 4-connected steps.
class ConfigurationSpace {
 public:
  ConfigurationSpace(const AbstractKnowledge& k, const Grid& grid, double radius,
                     std::vector<geometry::Footprint> footprints)
      : grid_(grid),
        radius_(radius),
        inner_workspace_{k.workspace.min + Vec2::Constant(radius), k.workspace.max - Vec2::Constant(radius)},
        blocked_(grid.size(), 0),
        reached_(grid.size(), 0),
        footprints_(std::move(footprints)) {
    for (const auto& f : footprints_) obstacles_.emplace_back(f.shape, f.pose);
    for (int iy = 0; iy < grid.rows(); ++iy) {
      for (int ix = 0; ix < grid.columns(); ++ix) blocked_[grid.index(ix, iy)] = !inner_workspace_.contains(grid.centre(ix, iy));
    }
    for (size_t i = 0; i < footprints_.size(); ++i) mark_blocked(footprints_[i], obstacles_[i]);
    flood_fill(grid.index_of(k.robot.start));
  }

  bool reached(size_t cell) const { return reached_[cell] != 0; }
  bool free_cell(size_t cell) const { return blocked_[cell] == 0; }

  bool free_point(const Vec2& p) const {
    return inner_workspace_.contains(p) &&
           std::none_of(obstacles_.begin(), obstacles_.end(), [&](const Obstacle& o) { return o.distance(p) < radius_; });
  }

 private:
  void mark_blocked(const geometry::Footprint& footprint, const Obstacle& obstacle) {
    const geometry::Rect reach = geometry::bounds(footprint.shape, footprint.pose);
    for (int iy = grid_.row(reach.min.y() - radius_); iy <= grid_.row(reach.max.y() + radius_); ++iy) {
      for (int ix = grid_.column(reach.min.x() - radius_); ix <= grid_.column(reach.max.x() + radius_); ++ix) {
        if (obstacle.distance(grid_.centre(ix, iy)) < radius_) blocked_[grid_.index(ix, iy)] = 1;
      }
    }
  }

  // Seeded at the start even if its cell centre is blocked: the robot is there, only its neighbours must
  // be free for it to move on.
  void flood_fill(size_t start) {
    std::vector<size_t> frontier{start};
    reached_[start] = 1;
    const auto nx = static_cast<size_t>(grid_.columns());
    while (!frontier.empty()) {
      const size_t cell = frontier.back();
      frontier.pop_back();
      const size_t ix = cell % nx;
      auto visit = [&](size_t next) {
        if (blocked_[next] || reached_[next]) return;
        reached_[next] = 1;
        frontier.push_back(next);
      };
      if (ix > 0) visit(cell - 1);
      if (ix + 1 < nx) visit(cell + 1);
      if (cell >= nx) visit(cell - nx);
      if (cell + nx < grid_.size()) visit(cell + nx);
    }
  }

  const Grid& grid_;
  double radius_;
  geometry::Rect inner_workspace_;
  std::vector<Obstacle> obstacles_;
  std::vector<std::uint8_t> blocked_;
  std::vector<std::uint8_t> reached_;
  std::vector<geometry::Footprint> footprints_;  // the obstacles' shapes live here
};

// Calls accept(point, cell) for the points that stand for a region on the grid until it returns true: the
// centres of the cells inside the region, then its centroid and vertices, so that a region smaller than a
// cell still has points. Returns whether some point was accepted.
template <class Accept>
bool any_region_point(const Grid& grid, const geometry::Polygon& region, Accept&& accept) {
  const geometry::Rect b = region.bounds();
  for (int iy = grid.row(b.min.y()); iy <= grid.row(b.max.y()); ++iy) {
    for (int ix = grid.column(b.min.x()); ix <= grid.column(b.max.x()); ++ix) {
      const Vec2 c = grid.centre(ix, iy);
      if (region.contains(c) && accept(c, grid.index(ix, iy), true)) return true;
    }
  }
  const Vec2 centroid = region.centroid();
  if (region.contains(centroid) && accept(centroid, grid.index_of(centroid), false)) return true;
  return std::any_of(region.vertices.begin(), region.vertices.end(),
                     [&](const Vec2& v) { return accept(v, grid.index_of(v), false); });
}

bool has_room(const Grid& grid, const ConfigurationSpace& space, const geometry::Polygon& region) {
  return any_region_point(grid, region, [&](const Vec2& p, size_t cell, bool is_center) {
    return is_center ? space.free_cell(cell) : space.free_point(p);
  });
}

// A point off the cell centres counts when it is free and its cell was reached: the two are at most
// 0.71 cell apart, below the robot's radius.
bool reaches(const Grid& grid, const ConfigurationSpace& space, const geometry::Polygon& region) {
  return any_region_point(grid, region, [&](const Vec2& p, size_t cell, bool is_center) {
    return space.reached(cell) && (is_center ? space.free_cell(cell) : space.free_point(p));
  });
}

std::string unpushable_names(const AbstractKnowledge& k) {
  std::string names;
  for (const auto& m : k.movable_bodies) {
    if (m.body_class == BodyClass::kFixed) names += (names.empty() ? "" : ", ") + m.name;
  }
  return names;
}

// Why `region` is out of reach, cheapest explanation that holds. The extra configuration spaces are
// built only when some proposition is invalid.
class Explainer {
 public:
  Explainer(const AbstractKnowledge& k, const Grid& grid, double cell_size, const ConfigurationSpace& robot_space)
      : k_(k), grid_(grid), cell_size_(cell_size), robot_space_(robot_space), unpushable_(unpushable_names(k)) {}

  InvalidProposition explain(const Proposition& p) {
    if (!unpushable_.empty() && reaches(grid_, without_unpushable_bodies(), p.region)) {
      return {p.name, Unreachability::kBlockedByUnpushableBodies,
              fmt::format("{}: cut off by bodies too heavy to push ({})", p.name, unpushable_)};
    }
    if (!reaches(grid_, probe(), p.region)) {
      return {p.name, Unreachability::kEnclosed, fmt::format("{}: region enclosed by fixed walls", p.name)};
    }
    if (!has_room(grid_, robot_space_, p.region)) {
      return {p.name, Unreachability::kNoRoomForRobot,
              fmt::format("{}: no room inside the region for the robot (radius {:.2f} m)", p.name, k_.robot.radius)};
    }
    return {p.name, Unreachability::kGapNarrowerThanRobot,
            fmt::format("{}: only reachable through a gap narrower than the robot (diameter {:.2f} m)", p.name,
                        2.0 * k_.robot.radius)};
  }

 private:
  const ConfigurationSpace& without_unpushable_bodies() {
    if (!without_unpushable_) {
      without_unpushable_.emplace(k_, grid_, k_.robot.radius, blocking_footprints(k_, false));
    }
    return *without_unpushable_;
  }

  // A near-point robot. Its radius of 0.75 cell keeps every grown obstacle wider than one grid step, so
  // the flood fill cannot step over a thin wall.
  const ConfigurationSpace& probe() {
    if (!probe_) probe_.emplace(k_, grid_, 0.75 * cell_size_, blocking_footprints(k_, true));
    return *probe_;
  }

  const AbstractKnowledge& k_;
  const Grid& grid_;
  double cell_size_;
  const ConfigurationSpace& robot_space_;
  std::string unpushable_;  // names, comma-separated
  std::optional<ConfigurationSpace> without_unpushable_;
  std::optional<ConfigurationSpace> probe_;
};

// The verdicts on object propositions. A body's centre moves as a disc of its inscribed radius would at
// least: wherever the body's centre can be, that disc fits too, so if the disc cannot get in, the body
// cannot. The discs' fields are shared by the bodies of one size and the propositions of one region set
// (a group of twenty boxes asks for one).
class ObjectJudge {
 public:
  ObjectJudge(const AbstractKnowledge& k, const base::Deadline& deadline) : k_(k), deadline_(deadline) {}

  // The verdict, and in `why` the kind of unreachability when it is unreachable.
  ObjectVerdict judge(const ObjectProposition& object, Unreachability& why) {
    const ltl::ObjectAtom atom = ltl::object_atom(object.name).value_or(ltl::ObjectAtom{object.name, object.name});
    ObjectVerdict verdict{object.name, atom.body, atom.region, object.bodies, object.regions, true, true, ""};
    std::string standing;  // the bodies that cannot move, inside
    for (int b : object.bodies) {
      const MovableBodyKnowledge& body = k_.movable_bodies[static_cast<size_t>(b)];
      const bool fixed = body.body_class == BodyClass::kFixed;
      const bool inside = starts_inside(body, object.regions);
      verdict.always_true = verdict.always_true && fixed && inside;
      if (fixed && inside) standing += (standing.empty() ? "" : ", ") + body.name;
      if (inside || !verdict.reachable) continue;
      if (fixed) {
        verdict.reachable = false, why = Unreachability::kBodyCannotMove;
        verdict.reason = fmt::format("{}: {} is {}", object.name, body.name, body.class_reason);
      } else if (const double inscribed = body.footprint.shape.centre_clearance();
                 // A centre outside its body (a concave one's) says nothing of where the body fits.
                 inscribed > 0.0 && !can_get_in(inscribed, object.regions, body.footprint.pose.position)) {
        verdict.reachable = false, why = Unreachability::kBodyCannotGetThere;
        const std::string unpushable = unpushable_names(k_);
        verdict.reason = fmt::format("{}: no way for the centre of {} into {}: every way in is narrower than {} ({:.2f} m "
                                     "across) among the fixed bodies{}",
                                     object.name, body.name, verdict.region, body.name, 2 * inscribed,
                                     unpushable.empty() ? "" : ", the bodies too heavy to push (" + unpushable + ")");
      }
    }
    if (verdict.always_true) {
      const MovableBodyKnowledge& first = k_.movable_bodies[static_cast<size_t>(object.bodies.front())];
      verdict.reason = object.bodies.size() == 1
                           ? fmt::format("{}: always true: {} stands in {} and is {}", object.name, first.name, verdict.region, first.class_reason)
                           : fmt::format("{}: always true: {} stand in {} and none of them can be pushed", object.name, standing, verdict.region);
    }
    return verdict;
  }

 private:
  bool starts_inside(const MovableBodyKnowledge& body, const std::vector<int>& regions) const {
    return std::any_of(regions.begin(), regions.end(), [&](int r) {
      return k_.propositions[static_cast<size_t>(r)].region.contains(body.footprint.pose.position);
    });
  }

  // Whether a disc of radius `inscribed` at `from` can get into one of `regions`; true, concluding nothing,
  // once the deadline has come (the run it belongs to then ends at its next check).
  bool can_get_in(double inscribed, const std::vector<int>& regions, const Vec2& from) {
    if (deadline_.reached()) return true;
    try {
      return field(inscribed, regions).reaches_target(from);
    } catch (const base::DeadlineReached&) {
      return true;
    }
  }

  // The field of a disc of radius `inscribed` towards `regions`, among what cannot move (the bodies too
  // heavy to push included: none of them is a body being judged, which can move).
  const geometry::DiscField& field(double inscribed, const std::vector<int>& regions) {
    auto& known = fields_[{inscribed, regions}];
    if (known) return *known;
    std::vector<geometry::Footprint> obstacles = blocking_footprints(k_, false);
    for (const auto& other : k_.movable_bodies) {
      if (other.body_class == BodyClass::kFixed) obstacles.push_back(other.footprint);
    }
    const Vec2 size = k_.workspace.size();
    // Fine enough that the margin the soundness costs (half a cell diagonal) is a few centimetres; a
    // million cells at most.
    const double cell = std::max(std::clamp(inscribed / 10.0, 0.01, 0.05), std::sqrt(size.x() * size.y() / 1e6));
    auto made = std::make_unique<geometry::DiscField>(k_.workspace, std::min(cell, inscribed), inscribed, obstacles, deadline_);
    std::vector<const geometry::Polygon*> polygons;
    for (int r : regions) polygons.push_back(&k_.propositions[static_cast<size_t>(r)].region);
    // A cell whose square touches a region is a target: within half its diagonal of it.
    made->compute_distances(made->cells_near(polygons, made->cell() * std::sqrt(2.0) / 2, deadline_), deadline_);
    known = std::move(made);  // only once whole: a field cut short by the deadline is not kept
    return *known;
  }

  const AbstractKnowledge& k_;
  const base::Deadline& deadline_;
  std::map<std::pair<double, std::vector<int>>, std::unique_ptr<geometry::DiscField>> fields_;
};

}  // namespace

std::vector<std::string> Feasibility::invalid_names() const {
  std::vector<std::string> names;
  for (const auto& p : invalid) names.push_back(p.name);
  return names;
}

std::vector<std::string> Feasibility::always_true_names() const {
  std::vector<std::string> names;
  for (const auto& o : objects) {
    if (o.always_true) names.push_back(o.name);
  }
  return names;
}

const InvalidProposition* Feasibility::find(const std::string& proposition) const {
  auto it = std::find_if(invalid.begin(), invalid.end(), [&](const auto& p) { return p.name == proposition; });
  return it == invalid.end() ? nullptr : &*it;
}

double grid_cell_size(const AbstractKnowledge& knowledge) {
  // Not above the robot's radius: grown obstacles are then wider than a grid step and cannot be leaked
  // through; not below 2 cm unless the robot is smaller, to keep the grid small.
  const double r = knowledge.robot.radius;
  const double preferred = std::min(std::clamp(r / 10.0, 0.02, 0.05), r);
  const Vec2 size = knowledge.workspace.size();
  const double needed_for_cap = std::sqrt(size.x() * size.y() / static_cast<double>(kMaxGridCells));
  return std::max(preferred, needed_for_cap);
}

Feasibility evaluate_feasibility(const AbstractKnowledge& knowledge, std::span<const ObjectProposition> objects,
                                 const base::Deadline& deadline) {
  Feasibility result;
  result.cell_size = grid_cell_size(knowledge);
  const Grid grid = Grid::covering(knowledge.workspace, result.cell_size);
  const ConfigurationSpace robot_space(knowledge, grid, knowledge.robot.radius, blocking_footprints(knowledge, true));
  Explainer explainer(knowledge, grid, result.cell_size, robot_space);
  for (const Proposition& p : knowledge.propositions) {
    if (!reaches(grid, robot_space, p.region)) result.invalid.push_back(explainer.explain(p));
  }
  ObjectJudge judge(knowledge, deadline);
  for (const ObjectProposition& object : objects) {
    Unreachability why = Unreachability::kBodyCannotGetThere;
    result.objects.push_back(judge.judge(object, why));
    const ObjectVerdict& verdict = result.objects.back();
    if (!verdict.reachable) {
      result.invalid.push_back({object.name, why, verdict.reason});
    }
  }
  return result;
}

}  // namespace physltl::knowledge
