#pragma once
// A body's outline on the floor, in the body's own frame; the body's pose puts it in the world. Three kinds,
// as scenario files write them: a box (a rectangle centred on the origin), a circle (an upright cylinder
// about its axis) and a polygon made of convex parts, its area centroid at the origin. Every query below
// is exact for every kind; a circle becomes a polygon only where a caller asks for one, from inside or from
// outside as its use needs.

#include "physltl/geometry/shapes.h"

#include <vector>

namespace physltl::geometry {

class Shape {
 public:
  enum class Kind { kBox, kCircle, kPolygon };

  Shape() = default;  // a box of no size
  static Shape box(const Vec2& half_extents);
  static Shape circle(double radius);
  // `outline`: a simple polygon in the body frame, its area centroid at the origin, its corners in the
  // author's order (faces are numbered along it); `parts`: convex polygons that tile it (the outline alone
  // when it is convex). Without an outline, the parts are the
  // whole of it (a mesh's footprint, which may come in pieces or with holes).
  static Shape polygon(Polygon outline, std::vector<Polygon> parts);

  Kind kind() const { return kind_; }
  bool is_box() const { return kind_ == Kind::kBox; }
  const Vec2& half_extents() const { return half_extents_; }  // a box's; zero otherwise
  double radius() const { return radius_; }                    // a circle's; zero otherwise
  // A box's four corners counter-clockwise, a polygon's outline as authored (either way round); empty for
  // a circle and for parts alone.
  const Polygon& outline() const { return outline_; }
  // Convex, counter-clockwise: a box's rectangle, a polygon's parts; none for a circle.
  const std::vector<Polygon>& parts() const { return parts_; }
  // Of the shape about its centre: no point of it is farther.
  double bound_radius() const { return bound_radius_; }
  double area() const;
  // The radius of the largest disc about the centre that lies inside the shape (a box's smaller half
  // extent): where the body's centre can go, such a disc fits.
  double centre_clearance() const;

 private:
  Kind kind_ = Kind::kBox;
  Vec2 half_extents_ = Vec2::Zero();
  double radius_ = 0.0;
  Polygon outline_;
  std::vector<Polygon> parts_;
  double bound_radius_ = 0.0;
};

// A shape where it stands: what the World says of a body.
struct Footprint {
  Pose2 pose;
  Shape shape;
};

inline Footprint box_footprint(const OrientedBox& box) { return {box.pose, Shape::box(box.half_extents)}; }

Vec2 to_world(const Pose2& pose, const Vec2& local);
Vec2 to_local(const Pose2& pose, const Vec2& world);
Polygon to_world(const Pose2& pose, const Polygon& local);

// Distance from `p` to the placed shape; 0 inside or on it.
double distance(const Shape& shape, const Pose2& pose, const Vec2& p);
inline bool contains(const Shape& shape, const Pose2& pose, const Vec2& p) { return distance(shape, pose, p) == 0.0; }
// Interiors intersect by more than `tolerance` (touching is not overlap).
bool overlap(const Shape& a, const Pose2& pose_a, const Shape& b, const Pose2& pose_b, double tolerance = 1e-9);
// The placed shape and the disc (the robot) overlap by more than `tolerance`.
bool overlap(const Shape& shape, const Pose2& pose, const Vec2& disc_center, double disc_radius, double tolerance = 1e-9);
bool inside(const Shape& shape, const Pose2& pose, const Rect& rect, double tolerance = 1e-9);
Rect bounds(const Shape& shape, const Pose2& pose);

// How a circle becomes a polygon where a caller needs corners: a regular polygon whose corners lie on the
// circle (inside it: paths that avoid it are no longer than paths that avoid the circle) or whose sides
// touch it (outside: whatever avoids it avoids the circle).
enum class CircleAs { kInscribed, kCircumscribed };
inline constexpr int kCircleCorners = 24;
// The placed shape's convex parts in the world frame (a circle as one polygon).
std::vector<Polygon> convex_parts_at(const Shape& shape, const Pose2& pose, CircleAs circle);

// Whether `p` lies in the placed shape as convex_parts_at(shape, pose, circle) outlines it: the shape
// itself, a circle as its polygon.
bool contains_as_parts(const Shape& shape, const Pose2& pose, const Vec2& p, CircleAs circle);

// The shape grown outwards by `by` metres: a box's half extents and a circle's radius longer by it, a
// polygon's sides moved out by it (the corners mitred, so the grown polygon holds the rounded one).
Shape grown(const Shape& shape, double by);

inline bool overlap(const Footprint& a, const Footprint& b, double tolerance = 1e-9) {
  return overlap(a.shape, a.pose, b.shape, b.pose, tolerance);
}

}  // namespace physltl::geometry
