#pragma once
// An oriented box with its axes computed once: inference and the reachability grid test many robot
// positions against few boxes, and OrientedBox recomputes its axes on every query.

#include "physltl/geometry/shapes.h"

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

class Obstacle {
 public:
  explicit Obstacle(const geometry::OrientedBox& box);

  double distance(const geometry::Vec2& p) const;

  // The t for which the robot's centre at origin + t * direction (direction of unit length) is closer than
  // `radius` to the box, i.e. inside the box grown by a disc: an interval, as that shape is convex.
  Interval closer_than(const geometry::Vec2& origin, const geometry::Vec2& direction, double radius) const;

 private:
  geometry::Vec2 local(const geometry::Vec2& world_vector) const {
    return {world_vector.dot(axis_x_), world_vector.dot(axis_y_)};
  }

  geometry::Vec2 center_;
  geometry::Vec2 axis_x_;
  geometry::Vec2 axis_y_;
  geometry::Vec2 half_extents_;
};

}  // namespace physltl::knowledge
