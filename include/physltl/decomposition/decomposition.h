#pragma once
// The triangular decomposition of the workspace minus the fixed bodies (paper Sec. 4.3, after Bhatia et
// al.): a conforming Delaunay mesh whose edges follow every region boundary, so each triangle lies in
// exactly one propositional region or in none (p0). Movable bodies are no holes (the robot can push them),
// but the outline of each body in clutter (another movable body within the robot's diameter, no fixed one),
// grown by the robot's radius, is made of mesh edges too: a triangle is then either clear of such a body or
// wholly where the robot's centre would touch it, and lanes between rows of boxes are triangles of their
// own (planning/route_choice).

#include "physltl/geometry/uniform_grid.h"
#include "physltl/scenario/world.h"

#include <array>
#include <vector>

namespace physltl::decomposition {

using scenario::Vec2;

struct Triangle {
  std::array<Vec2, 3> corners;
  Vec2 centroid;
  double area = 0.0;
  int region = -1;             // index into World::regions; -1 outside every region (p0)
  std::vector<int> neighbors;  // triangles sharing an edge

  // The point a pair of numbers uniform in [0, 1) names, uniform over the triangle: how a planner samples
  // a point in it with its own generator.
  Vec2 point_at(double u, double v) const {
    if (u + v > 1.0) u = 1.0 - u, v = 1.0 - v;
    return corners[0] + u * (corners[1] - corners[0]) + v * (corners[2] - corners[0]);
  }
};

struct DecompositionOptions {
  // Longest edge of a triangle, in metres; 0 derives it from the workspace (about 1/20 of its diagonal).
  double max_edge = 0.0;
};

class Decomposition {
 public:
  static Decomposition build(const scenario::World& world, const DecompositionOptions& options = {});

  const std::vector<Triangle>& triangles() const { return triangles_; }
  int size() const { return static_cast<int>(triangles_.size()); }
  // The triangle containing `p`, or the nearest one when `p` lies on no triangle (inside a fixed body
  // or out of the workspace, up to rounding).
  int locate(const Vec2& p) const;

 private:
  std::vector<Triangle> triangles_;
  // A uniform grid of buckets listing the triangles overlapping each cell, for locate().
  // Buckets of triangles on a grid about one triangle edge wide, for locate().
  void bucket_triangles(const geometry::Rect& bounds, double cell);
  geometry::UniformGrid grid_;
  std::vector<std::vector<int>> buckets_;  // per cell of grid_, the triangles whose bounds reach into it
};

}  // namespace physltl::decomposition
