#pragma once
// A footprint with its axes computed once: inference and the reachability grid test many robot positions
// against few bodies, and the shapes' own queries recompute the axes every time.

#include "physltl/geometry/shape.h"
#include "physltl/geometry/shapes.h"

#include <vector>

namespace physltl::knowledge {

// Parameters t of a line; open, empty when lo >= hi.
struct Interval {
  double lo = 0.0;
  double hi = 0.0;
  bool empty() const { return lo >= hi; }
};

// t with origin + t * direction strictly inside the axis-aligned rectangle of half extents `half` centred
// at the origin of coordinates.
Interval inside_rectangle(const geometry::Vec2& origin, const geometry::Vec2& direction, const geometry::Vec2& half);

// t with |origin + t * direction - center| < radius, direction of unit length.
Interval inside_disc(const geometry::Vec2& origin, const geometry::Vec2& direction, const geometry::Vec2& center, double radius);
// t with origin + t * direction strictly inside the convex, counter-clockwise polygon `v` (Cyrus-Beck).
Interval inside_convex(const geometry::Vec2& origin, const geometry::Vec2& direction, const std::vector<geometry::Vec2>& v);

// A body's footprint where it stands, as INFERENCE and the reachability grid ask about it.
class Obstacle {
 public:
  // `shape` must outlive the obstacle.
  Obstacle(const geometry::Shape& shape, const geometry::Pose2& pose);

  double distance(const geometry::Vec2& p) const;

  // The t for which the robot's centre at origin + t * direction (direction of unit length) is closer than
  // `radius` to the footprint, i.e. inside it grown by a disc: one interval per convex part (a box and a
  // circle have one), appended to `out` unless empty.
  void closer_than(const geometry::Vec2& origin, const geometry::Vec2& direction, double radius,
                   std::vector<Interval>& out) const;

  const geometry::Shape& shape() const { return shape_; }
  const geometry::Pose2& pose() const { return pose_; }
  const geometry::Vec2& center() const { return center_; }
  // A vector of the world in the body's frame.
  geometry::Vec2 local(const geometry::Vec2& world_vector) const {
    return {world_vector.dot(axis_x_), world_vector.dot(axis_y_)};
  }

 private:
  const geometry::Shape& shape_;
  geometry::Pose2 pose_;
  geometry::Vec2 center_;
  geometry::Vec2 axis_x_;
  geometry::Vec2 axis_y_;
};

}  // namespace physltl::knowledge
