#include "physltl/geometry/free_space.h"

#include "free_space_mesh.h"
#include "free_space_search.h"
#include "shape_kinds.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace physltl::geometry {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

double distance_to_segment(const Vec2& p, const Vec2& a, const Vec2& b, Vec2& closest) {
  const Vec2 d = b - a;
  const double length2 = d.squaredNorm();
  const double t = length2 > 0 ? std::clamp((p - a).dot(d) / length2, 0.0, 1.0) : 0.0;
  closest = a + t * d;
  return (p - closest).norm();
}

bool segments_cross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
  const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 && d4 != 0;
}

// Per edge of a convex polygon, what counts as a rounding error of the side a point is on: 1e-9 of its
// length (worked out once: the visibility tests ask it millions of times).
std::vector<double> edge_margins(const Polygon& polygon) {
  const auto& v = polygon.vertices;
  std::vector<double> margins;
  for (size_t i = 0; i < v.size(); ++i) margins.push_back(1e-9 * (v[i + 1 == v.size() ? 0 : i + 1] - v[i]).norm());
  return margins;
}

// Whether some point of segment ab lies in the interior of the convex, counter-clockwise polygon, by more
// than a rounding error (`margins`, edge_margins of it): the part of the segment left of every edge
// (Cyrus-Beck) is not empty.
bool enters(const Vec2& a, const Vec2& b, const Polygon& polygon, const std::vector<double>& margins) {
  double lo = 0.0, hi = 1.0;
  const Vec2 d = b - a;
  const auto& v = polygon.vertices;
  for (size_t i = 0; i < v.size(); ++i) {
    const Vec2 edge = v[i + 1 == v.size() ? 0 : i + 1] - v[i];
    const double at_a = cross(edge, a - v[i]) - margins[i];  // > 0: a is inside this edge's half-plane
    const double slope = cross(edge, d);
    if (slope == 0.0) {
      if (at_a <= 0.0) return false;
    } else if (slope > 0.0) {
      lo = std::max(lo, -at_a / slope);
    } else {
      hi = std::min(hi, -at_a / slope);
    }
    if (lo >= hi) return false;
  }
  return hi - lo > 1e-12;
}

}  // namespace

Polygon grown_from_inside(const OrientedBox& box, double radius, int chords_per_corner) {
  const Vec2 h = box.half_extents;
  const Eigen::Rotation2Dd rotation(box.pose.yaw);
  const std::array<Vec2, 4> corners = {Vec2(h.x(), -h.y()), Vec2(h.x(), h.y()), Vec2(-h.x(), h.y()), Vec2(-h.x(), -h.y())};
  Polygon grown;
  for (int c = 0; c < 4; ++c) {
    const double start = (c - 1) * std::numbers::pi / 2;  // the arc of corner c, counter-clockwise
    for (int k = 0; k <= chords_per_corner; ++k) {
      const double angle = start + k * (std::numbers::pi / 2) / chords_per_corner;
      const Vec2 local = corners[static_cast<size_t>(c)] + radius * Vec2(std::cos(angle), std::sin(angle));
      grown.vertices.push_back(box.pose.position + rotation * local);
    }
  }
  return grown;
}

std::vector<Polygon> grown_from_inside(const Shape& shape, const Pose2& pose, double radius) {
  return kind_of(shape).grown_from_inside(shape, pose, radius);
}

double distance(const Vec2& p, const Polygon& polygon) {
  if (polygon.vertices.size() == 1) return (p - polygon.vertices[0]).norm();
  if (polygon.contains(p)) return 0.0;
  double best = kInfinity;
  Vec2 closest;
  const auto& v = polygon.vertices;
  for (size_t i = 0; i < v.size(); ++i) best = std::min(best, distance_to_segment(p, v[i], v[(i + 1) % v.size()], closest));
  return best;
}

double depth_inside(const Vec2& p, const Polygon& polygon) {
  if (polygon.vertices.size() < 3 || !polygon.contains(p)) return 0.0;
  double best = kInfinity;
  Vec2 closest;
  const auto& v = polygon.vertices;
  for (size_t i = 0; i < v.size(); ++i) best = std::min(best, distance_to_segment(p, v[i], v[(i + 1) % v.size()], closest));
  return best;
}

double distance(const Polygon& a, const Polygon& b, Vec2& closest_a, Vec2& closest_b) {
  const auto& va = a.vertices;
  const auto& vb = b.vertices;
  // Overlapping: a vertex inside the other polygon, or two edges crossing.
  for (const Vec2& p : va) {
    if (vb.size() > 2 && b.contains(p)) return closest_a = closest_b = p, 0.0;
  }
  for (const Vec2& p : vb) {
    if (va.size() > 2 && a.contains(p)) return closest_a = closest_b = p, 0.0;
  }
  double best = kInfinity;
  Vec2 closest;
  auto try_point = [&](const Vec2& p, const std::vector<Vec2>& other, bool p_in_a) {
    for (size_t i = 0; i < other.size(); ++i) {
      const double d = distance_to_segment(p, other[i], other[(i + 1) % other.size()], closest);
      if (d < best) {
        best = d;
        closest_a = p_in_a ? p : closest;
        closest_b = p_in_a ? closest : p;
      }
    }
  };
  for (const Vec2& p : va) try_point(p, vb, true);
  for (const Vec2& p : vb) try_point(p, va, false);
  for (size_t i = 0; i < va.size() && va.size() > 1; ++i) {
    for (size_t j = 0; j < vb.size() && vb.size() > 1; ++j) {
      if (segments_cross(va[i], va[(i + 1) % va.size()], vb[j], vb[(j + 1) % vb.size()])) {
        return closest_a = closest_b = va[i], 0.0;
      }
    }
  }
  return best;
}

FreeSpace::FreeSpace(std::vector<Polygon> obstacles, const Rect& bounds)
    : obstacles_(std::move(obstacles)), bounds_(bounds) {
  for (Polygon& o : obstacles_) {
    if (o.signed_area() < 0) std::reverse(o.vertices.begin(), o.vertices.end());
    obstacle_bounds_.push_back(o.bounds());
    obstacle_margins_.push_back(edge_margins(o));
  }
  // About one obstacle per cell.
  const Vec2 size = bounds_.size().cwiseMax(Vec2::Constant(1e-9));
  const double cell = std::max(std::sqrt(size.x() * size.y() / std::max<double>(1.0, static_cast<double>(obstacles_.size()))), 1e-3);
  grid_ = UniformGrid(bounds_.min, cell, std::min(static_cast<int>(std::ceil(size.x() / cell)), kMaxCellsPerSide),
                      std::min(static_cast<int>(std::ceil(size.y() / cell)), kMaxCellsPerSide));
  cells_.assign(grid_.size(), {});
  for (size_t i = 0; i < obstacles_.size(); ++i) {
    const Rect& r = obstacle_bounds_[i];
    if (r.max.x() < bounds_.min.x() || r.min.x() > bounds_.max.x() || r.max.y() < bounds_.min.y() || r.min.y() > bounds_.max.y()) {
      continue;  // wholly outside where a path may go
    }
    for (int y = grid_.row(r.min.y()); y <= grid_.row(r.max.y()); ++y) {
      for (int x = grid_.column(r.min.x()); x <= grid_.column(r.max.x()); ++x) cells_[grid_.index(x, y)].push_back(static_cast<int>(i));
    }
  }
}

bool FreeSpace::free(const Vec2& a, const Vec2& b) const {
  if (!bounds_.contains(a) || !bounds_.contains(b)) return false;
  const Rect span{a.cwiseMin(b), a.cwiseMax(b)};
  const Vec2 way = b - a;
  const auto blocks = [&](int i) {
    const Rect& r = obstacle_bounds_[static_cast<size_t>(i)];
    if (r.max.x() < span.min.x() || r.min.x() > span.max.x() || r.max.y() < span.min.y() || r.min.y() > span.max.y()) {
      return false;
    }
    // Bounds wholly on one side of the segment's line, touching it at most: the obstacle within them has
    // no interior point on the line (a way along a row of obstacles grazes each, and this is four cross
    // products where the test below is one per edge and a division). A point has no line.
    const double s1 = cross(way, r.min - a), s2 = cross(way, Vec2(r.max.x(), r.min.y()) - a);
    const double s3 = cross(way, r.max - a), s4 = cross(way, Vec2(r.min.x(), r.max.y()) - a);
    if (a != b && (std::min({s1, s2, s3, s4}) >= 0.0 || std::max({s1, s2, s3, s4}) <= 0.0)) return false;
    return enters(a, b, obstacles_[static_cast<size_t>(i)], obstacle_margins_[static_cast<size_t>(i)]);
  };
  // The cells the segment crosses, in order (Amanatides and Woo's traversal); an obstacle in several of
  // them is tested in each, which costs less than remembering which were.
  const Vec2 from = (a - grid_.origin()) / grid_.cell(), to = (b - grid_.origin()) / grid_.cell();
  int x = grid_.column(a.x()), y = grid_.row(a.y());
  const int last_x = grid_.column(b.x()), last_y = grid_.row(b.y());
  const Vec2 d = to - from;
  const int step_x = d.x() > 0 ? 1 : -1, step_y = d.y() > 0 ? 1 : -1;
  const double delta_x = d.x() != 0 ? std::abs(1.0 / d.x()) : kInfinity, delta_y = d.y() != 0 ? std::abs(1.0 / d.y()) : kInfinity;
  double next_x = d.x() != 0 ? ((step_x > 0 ? x + 1 - from.x() : from.x() - x) * delta_x) : kInfinity;
  double next_y = d.y() != 0 ? ((step_y > 0 ? y + 1 - from.y() : from.y() - y) * delta_y) : kInfinity;
  while (true) {
    for (int i : cells_[grid_.index(x, y)]) {
      if (blocks(i)) return false;
    }
    if (x == last_x && y == last_y) return true;
    // Step into the neighbouring cell the segment reaches first; at a corner both ways, so no cell it
    // touches is skipped.
    if (next_x < next_y) {
      x += step_x, next_x += delta_x;
    } else if (next_y < next_x) {
      y += step_y, next_y += delta_y;
    } else {
      for (int i : cells_[grid_.index(std::clamp(x + step_x, 0, grid_.columns() - 1), y)]) {
        if (blocks(i)) return false;
      }
      x += step_x, next_x += delta_x;
      y += step_y, next_y += delta_y;
    }
    if (!grid_.contains(x, y)) return true;
  }
}

std::vector<std::vector<double>> FreeSpace::distances(const std::vector<Polygon>& places, const base::Deadline& deadline) const {
  const auto obstacles_at = [&](const Vec2& p) -> const std::vector<int>& { return cells_[grid_.index_of(p)]; };
  const FreeMesh mesh = triangulate_free_space(obstacles_, obstacles_at, bounds_, places, deadline);
  std::vector<std::vector<double>> lengths;
  for (size_t from = 0; from < places.size(); ++from) lengths.push_back(distances_from_place(mesh, static_cast<int>(from), deadline));
  return lengths;
}

double FreeSpace::distance(const Polygon& from, const Polygon& to) const { return distances({from, to})[0][1]; }

}  // namespace physltl::geometry
