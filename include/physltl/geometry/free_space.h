#pragma once
// Shortest paths of a point among convex polygonal obstacles inside a rectangle. With each obstacle the
// configuration-space obstacle of a disc robot (a fixed body grown by the robot's radius), these are
// shortest paths of the robot's centre.

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
  // `obstacles` convex; `bounds` where the point may go.
  FreeSpace(std::vector<Polygon> obstacles, const Rect& bounds);

  // Whether the segment stays out of every obstacle's interior (touching a boundary is allowed).
  bool free(const Vec2& a, const Vec2& b) const;

  // The lengths of shortest obstacle-avoiding paths between places (each a polygon, or one vertex for a
  // point): [i][j] from any point of place i to any point of place j, the parts of a place inside
  // obstacles not counting; infinity where there is none. Exact but for a nanometre at each corner passed,
  // on the short side (touching obstacles are shrunk apart by that much, free_space_mesh.cpp): an any-angle
  // search over the free space's triangles from each place (free_space_search.h), whose cost follows the
  // area it sweeps, not the pairs of corners that see each other. Checks `deadline` as it goes and throws
  // DeadlineReached.
  std::vector<std::vector<double>> distances(const std::vector<Polygon>& places, const base::Deadline& deadline = {}) const;
  double distance(const Polygon& from, const Polygon& to) const;  // one pair

 private:
  std::vector<Polygon> obstacles_;
  std::vector<Rect> obstacle_bounds_;
  std::vector<std::vector<double>> obstacle_margins_;  // per obstacle, per edge: the rounding error of a side test
  // The obstacles overlapping each cell of a uniform grid over the bounds: a segment is tested against the
  // obstacles of the cells it crosses, not all of them.
  static constexpr int kMaxCellsPerSide = 4096;
  UniformGrid grid_;
  std::vector<std::vector<int>> cells_;  // per cell of grid_, the obstacles whose bounds reach into it
  Rect bounds_;
};

// Distance from a point to a polygon (0 inside), and between two polygons (0 when they overlap) with the
// closest points.
double distance(const Vec2& p, const Polygon& polygon);
// How far inside `polygon` the point lies: its distance to the nearest edge, 0 on or outside it.
double depth_inside(const Vec2& p, const Polygon& polygon);
double distance(const Polygon& a, const Polygon& b, Vec2& closest_a, Vec2& closest_b);

}  // namespace physltl::geometry
