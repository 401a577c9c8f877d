#pragma once
// Planar shapes of the workspace: the robot moves on the floor, so every footprint is 2D.

#include <Eigen/Core>

#include <array>
#include <vector>

namespace physltl::geometry {

using Vec2 = Eigen::Vector2d;

// The z component of a x b: positive when b turns left from a.
inline double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

struct Pose2 {
  Vec2 position = Vec2::Zero();
  double yaw = 0.0;  // radians, counter-clockwise from +x
  friend bool operator==(const Pose2& a, const Pose2& b) { return a.position == b.position && a.yaw == b.yaw; }  // bit for bit
};

// An axis-aligned rectangle, e.g. the workspace bounds.
struct Rect {
  Vec2 min = Vec2::Zero();
  Vec2 max = Vec2::Zero();

  bool contains(const Vec2& p) const;
  Vec2 size() const { return max - min; }
};

// A rectangle rotated about its centre: the footprint of a wall or a box.
struct OrientedBox {
  Pose2 pose;
  Vec2 half_extents = Vec2::Zero();

  std::array<Vec2, 4> corners() const;  // counter-clockwise
  Vec2 axis(int i) const;              // body-frame x (0) or y (1) axis in the world frame
  bool contains(const Vec2& p) const;
  double distance_to(const Vec2& p) const;  // 0 inside
};

// A simple polygon (no self-intersections), vertices in either orientation.
struct Polygon {
  std::vector<Vec2> vertices;

  static Polygon from_rect(const Rect& r);
  static Polygon from_box(const OrientedBox& b);

  double signed_area() const;  // > 0 when counter-clockwise
  Vec2 centroid() const;
  Rect bounds() const;
  bool contains(const Vec2& p) const;  // interior or boundary
  bool is_simple() const;              // no two non-adjacent edges meet
};

// Interiors intersect by more than `tolerance` (touching along an edge or at a corner is not overlap).
bool overlap(const OrientedBox& a, const OrientedBox& b, double tolerance = 1e-9);
bool overlap(const Polygon& a, const Polygon& b);
bool overlap(const OrientedBox& box, const Vec2& disc_center, double disc_radius, double tolerance = 1e-9);
bool inside(const OrientedBox& box, const Rect& rect, double tolerance = 1e-9);
bool inside(const Polygon& polygon, const Rect& rect, double tolerance = 1e-9);

}  // namespace physltl::geometry
