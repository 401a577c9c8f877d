#pragma once
// Shortest paths of a point among convex polygonal obstacles inside a rectangle: a visibility graph over the
// obstacles' corners. With each obstacle the configuration-space obstacle of a disc robot (a fixed body
// grown by the robot's radius), these are shortest paths of the robot's centre.

#include "physltl/base/deadline.h"
#include "physltl/geometry/shape.h"
#include "physltl/geometry/shapes.h"
#include "physltl/geometry/uniform_grid.h"

#include <utility>
#include <vector>

namespace physltl::geometry {

// A fixed body's footprint grown by `radius` (the set of disc centres that overlap it), approximated from
// inside: the rounded corners become chords of their arcs, so the polygon is contained in the true set
// and a path that avoids it is at most as long as one that avoids the true set.
Polygon grown_from_inside(const OrientedBox& box, double radius, int chords_per_corner = 2);
// The same for a placed shape of any kind, one convex polygon per part: a circle grown is a circle, drawn
// with its corners on it; a polygon's corners round off into chords.
std::vector<Polygon> grown_from_inside(const Shape& shape, const Pose2& pose, double radius);

class FreeSpace {
 public:
  // `obstacles` convex; `bounds` where the point may go. Its visibility graph costs the square of the
  // corners: the construction checks `deadline` as it goes and throws DeadlineReached.
  FreeSpace(std::vector<Polygon> obstacles, const Rect& bounds, const Deadline& deadline = {});

  // Whether the segment stays out of every obstacle's interior (touching a boundary is allowed).
  bool free(const Vec2& a, const Vec2& b) const;

  // The length of a shortest obstacle-avoiding path from any point of `from` to any point of `to` (each a
  // polygon, or one vertex for a point; parts inside obstacles do not count); infinity when there is none.
  double distance(const Polygon& from, const Polygon& to) const;

  // The same for many pairs: prepare each polygon once, search from each source once.
  struct Place {
    Polygon polygon;
    std::vector<Vec2> points;  // its corners, and where obstacles' edges cross its edges
    std::vector<std::pair<Vec2, Vec2>> obstacle_edges;  // of the obstacles that may reach into it
    std::vector<double> from_corner;  // per corner of the free space: the straight way in (see reach())
  };
  Place place(const Polygon& polygon) const;
  std::vector<double> distances_from(const Place& from) const;  // to every corner of the free space
  double distance_to(const std::vector<double>& from_corners, const Place& from, const Place& to) const;

 private:
  // The shortest straight segment from `from` into the free part of `to`; infinity if every one is blocked.
  double reach(const Vec2& from, const Place& to) const;

  std::vector<Polygon> obstacles_;
  std::vector<Rect> obstacle_bounds_;
  std::vector<std::vector<double>> obstacle_margins_;  // per obstacle, per edge: the rounding error of a side test
  // The obstacles overlapping each cell of a uniform grid over the bounds: a segment is tested against the
  // obstacles of the cells it crosses, not all of them.
  static constexpr int kMaxCellsPerSide = 4096;
  UniformGrid grid_;
  std::vector<std::vector<int>> cells_;  // per cell of grid_, the obstacles whose bounds reach into it
  Rect bounds_;
  std::vector<Vec2> corners_;                           // obstacle corners inside bounds and no obstacle
  std::vector<std::vector<std::pair<int, double>>> edges_;  // per corner: visible corners and distances
};

// Distance from a point to a polygon (0 inside), and between two polygons (0 when they overlap) with the
// closest points.
double distance(const Vec2& p, const Polygon& polygon);
double distance(const Polygon& a, const Polygon& b, Vec2& closest_a, Vec2& closest_b);

}  // namespace physltl::geometry
