#include "object_lead.h"

#include "physltl/geometry/shortest_paths.h"

#include "physltl/knowledge/face_set.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace physltl::planners::knowledge {

using geometry::Vec2;

namespace {

// The way's grid: fine enough for doorways a body barely fits through, coarse enough to stay small.
constexpr double kMaxWayCells = 250'000;
// How far along its way the body is aimed at, from where it stands: far enough to smooth the grid's steps,
// near enough to follow a bend.
constexpr double kWayLookahead = 1.0;  // m
// The robot acts on its own (target()) within this straight distance of the body, and when the
// decomposition's way there is not much longer (no wall in between).
constexpr double kNear = 2.5;  // m
constexpr double kNearDetour = 1.5;
constexpr int kApproachTriangles = 4;  // triangles ahead the approach aims at
constexpr std::size_t kCachedTriangles = 64;
// The robot goes round the body with this much room between them.
constexpr double kRoundClearance = 0.08;  // m

Vec2 unit(const Vec2& v) {
  const double n = v.norm();
  return n > 1e-12 ? Vec2(v / n) : Vec2(1.0, 0.0);
}

// Whether the segment from `a` to `b` passes through the placed shape (sampled every few centimetres).
bool crosses(const geometry::Shape& shape, const geometry::Pose2& pose, const Vec2& a, const Vec2& b) {
  const int samples = std::max(2, static_cast<int>((b - a).norm() / 0.05));
  for (int i = 1; i < samples; ++i) {
    if (geometry::contains(shape, pose, a + (b - a) * (static_cast<double>(i) / samples))) return true;
  }
  return false;
}

}  // namespace

ObjectLead::ObjectLead(const scenario::World& world, const physltl::knowledge::AbstractKnowledge& knowledge,
                       const decomposition::Decomposition& decomposition)
    : world_(world), knowledge_(knowledge), decomposition_(decomposition), regions_(world) {}

const geometry::DiscField& ObjectLead::way(const physltl::knowledge::Labelling::NamedPart& part, int body_index, int place) {
  std::unique_ptr<geometry::DiscField>& way = ways_[{body_index, place}];
  if (way) return *way;
  const auto& body = knowledge_.movable_bodies[static_cast<std::size_t>(body_index)];
  std::vector<geometry::Footprint> obstacles;
  for (const auto& f : knowledge_.fixed_bodies) obstacles.push_back(f.footprint);
  for (std::size_t b = 0; b < knowledge_.movable_bodies.size(); ++b) {
    const auto& other = knowledge_.movable_bodies[b];
    if (static_cast<int>(b) != body_index && other.body_class == physltl::knowledge::BodyClass::kFixed) obstacles.push_back(other.footprint);
  }
  const double inscribed = body.footprint.shape.centre_clearance();
  const Vec2 size = knowledge_.workspace.size();
  const double cell = std::max({0.5 * inscribed, 0.05, std::sqrt(size.x() * size.y() / kMaxWayCells)});
  // A centre outside its (concave) body: the centre's own way, on the grid of the workspace's size.
  way = std::make_unique<geometry::DiscField>(knowledge_.workspace, inscribed > 0.0 ? std::min(cell, inscribed) : cell, inscribed, obstacles);
  // Place 0 is outside every region of the part's sets; place k inside one of set k.
  std::vector<const geometry::Polygon*> regions;
  for (std::size_t set = 0; set < part.region_sets.size(); ++set) {
    if (place > 0 && set != static_cast<std::size_t>(place - 1)) continue;
    for (int r : part.region_sets[set]) regions.push_back(&world_.regions[static_cast<std::size_t>(r)].polygon);
  }
  std::vector<bool> targets = way->cells_near(regions, 0.0);
  if (place == 0) targets.flip();
  way->compute_distances(targets);
  return *way;
}

bool ObjectLead::placed(const physltl::knowledge::Labelling::NamedPart& part, int place, const Vec2& centre) const {
  return part.place_of_region(regions_.at(centre)) == place;
}

ObjectLead::Goal ObjectLead::goal(const physltl::knowledge::Labelling& labelling, const planning::BodyMove& move,
                                  const std::function<Vec2(int)>& centre_of) {
  const physltl::knowledge::Labelling::NamedPart& part = labelling.named_parts()[static_cast<std::size_t>(move.named)];
  if (part.bodies.size() == 1) return {part.bodies.front(), &way(part, part.bodies.front(), move.place)};
  Goal best{part.bodies.front(), nullptr};
  double least = std::numeric_limits<double>::infinity();
  for (int body : part.bodies) {
    // A body already where the move wants it, as the labelling sees it, is not the one to push on.
    const Vec2 centre = centre_of(body);
    if (placed(part, move.place, centre)) continue;
    const Goal goal{body, &way(part, body, move.place)};
    const double left = remaining(goal, centre);
    if (left < least || best.way == nullptr) best = goal, least = left;
  }
  if (best.way == nullptr) best.way = &way(part, best.body, move.place);
  return best;
}

int ObjectLead::placed_bodies(const physltl::knowledge::Labelling& labelling, const planning::BodyMove& move,
                              const std::function<Vec2(int)>& centre_of) const {
  const physltl::knowledge::Labelling::NamedPart& part = labelling.named_parts()[static_cast<std::size_t>(move.named)];
  return static_cast<int>(std::count_if(part.bodies.begin(), part.bodies.end(),
                                        [&](int body) { return placed(part, move.place, centre_of(body)); }));
}

double ObjectLead::remaining(const Goal& goal, const Vec2& centre) {
  const double d = goal.way->distance(centre);
  if (d < geometry::DiscField::kUnreachable) return d;
  // Against a wall the centre's cell may count as blocked (the field keeps half a cell of margin): the way
  // from the nearest free cell.
  const Vec2 free = goal.way->nearest_free(centre, 3 * goal.way->cell());
  return goal.way->distance(free) + (free - centre).norm();
}

const std::vector<double>& ObjectLead::distances_to_triangle(int triangle) {
  const auto known = triangle_distances_.find(triangle);
  if (known != triangle_distances_.end()) return known->second;
  if (triangle_distances_.size() >= kCachedTriangles) triangle_distances_.clear();
  const auto& triangles = decomposition_.triangles();
  geometry::ShortestPaths ways(triangles.size());
  ways.seed(triangle, 0.0);
  ways.run([&](int t, double d) {
    for (int n : triangles[static_cast<std::size_t>(t)].neighbors) {
      ways.relax(t, n, d + (triangles[static_cast<std::size_t>(n)].centroid - triangles[static_cast<std::size_t>(t)].centroid).norm());
    }
    return true;
  });
  std::vector<double> distance = ways.distances();
  return triangle_distances_.emplace(triangle, std::move(distance)).first->second;
}

std::optional<Vec2> ObjectLead::approach(const Vec2& robot, const Vec2& body) {
  const double straight = (body - robot).norm();
  const std::vector<double>& distance = distances_to_triangle(decomposition_.locate(body));
  int at = decomposition_.locate(robot);
  if (straight <= kNear && distance[static_cast<std::size_t>(at)] <= kNearDetour * straight + 0.5) return std::nullopt;
  const auto& triangles = decomposition_.triangles();
  for (int step = 0; step < kApproachTriangles; ++step) {
    int best = at;
    for (int n : triangles[static_cast<std::size_t>(at)].neighbors) {
      if (distance[static_cast<std::size_t>(n)] < distance[static_cast<std::size_t>(best)]) best = n;
    }
    if (best == at) break;
    at = best;
  }
  return triangles[static_cast<std::size_t>(at)].centroid;
}

Vec2 ObjectLead::target(const Goal& goal, const scenario::EnvironmentState& state, const physltl::knowledge::Kappa& kappa,
                        planning::Random& random) const {
  const geometry::Pose2& pose = state.movable_poses[static_cast<std::size_t>(goal.body)];
  const Vec2& robot = state.robot_position;
  const Vec2 from = goal.way->nearest_free(pose.position, 3 * goal.way->cell());
  const Vec2 wanted = unit(goal.way->ahead_of(from, kWayLookahead) - pose.position);
  // The active side whose push helps most along the way.
  const auto& body = knowledge_.movable_bodies[static_cast<std::size_t>(goal.body)];
  const physltl::knowledge::MRegionTemplate* best = nullptr;
  double best_help = -std::numeric_limits<double>::infinity();
  for (const auto& m : body.mregions) {
    if (!kappa.bodies[static_cast<std::size_t>(goal.body)].active_faces.contains(m.face)) continue;
    const double help = physltl::knowledge::push_direction(m, pose).dot(wanted);
    if (help > best_help) best_help = help, best = &m;
  }
  if (best == nullptr) {
    // No side to push from: let the robot wander near the body; the search's other expansions go on.
    const double a = random.uniform(-3.14159265358979, 3.14159265358979);
    return pose.position + (body.bound_radius + 2 * world_.robot.radius) * Vec2(std::cos(a), std::sin(a));
  }
  const Vec2 push = physltl::knowledge::push_direction(*best, pose);
  if (physltl::knowledge::mregion_at(*best, pose).contains(robot)) return robot + push;
  // The middle of the side's contact segment, where the robot touches it; round the body if it is in the way.
  const Eigen::Rotation2Dd rotation(pose.yaw);
  const Vec2 contact = pose.position + rotation * (0.5 * (best->contact_from + best->contact_to));
  // Where the robot's centre would hit the body (the contact point lies just outside), and the corners
  // it goes round by.
  const double r = world_.robot.radius;
  const geometry::Shape blocking = geometry::grown(body.footprint.shape, 0.9 * r);
  if (!crosses(blocking, pose, robot, contact)) return contact;
  const geometry::Shape round = geometry::grown(body.footprint.shape, r + kRoundClearance);
  Vec2 corner_target = contact;
  double shortest = std::numeric_limits<double>::infinity();
  // Every part's corners: a compound body's outline is the union of its parts.
  for (const geometry::Polygon& part : geometry::convex_parts_at(round, pose, geometry::CircleAs::kCircumscribed)) {
    for (const Vec2& corner : part.vertices) {
      if (crosses(blocking, pose, robot, corner)) continue;
      const double way = (corner - robot).norm() + (contact - corner).norm();
      if (way < shortest) shortest = way, corner_target = corner;
    }
  }
  return corner_target;
}

}  // namespace physltl::planners::knowledge
