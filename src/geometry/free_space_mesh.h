#pragma once
// The free space cut into triangles: the part of a rectangle outside convex obstacles, with the outlines of
// the places whose distances are asked as edges too, so that each triangle is wholly inside or wholly
// outside each obstacle and each place. The ground the any-angle search (free_space_search.h) walks.

#include "physltl/base/deadline.h"
#include "physltl/geometry/shapes.h"

#include <array>
#include <functional>
#include <vector>

namespace physltl::geometry {

struct FreeMesh {
  struct Triangle {
    std::array<int, 3> vertex;          // counter-clockwise
    std::array<int, 3> neighbour;       // across edge e (vertex[e] to vertex[e + 1]): a free triangle, or -1
    std::array<int, 3> neighbour_edge;  // that edge's number in the neighbour
  };
  std::vector<Vec2> vertices;
  // Per vertex: something not free (an obstacle, or the outside of the bounds) touches it, so a shortest
  // path may turn there.
  std::vector<char> corner;
  std::vector<Triangle> triangles;  // the free ones only
  // The free triangles round each vertex: those of vertex v are incident[incident_start[v] ..
  // incident_start[v + 1]).
  std::vector<int> incident_start, incident;
  // Per place, the free triangles inside it (a polygon place) or its vertex (a place of one point; -1
  // when it is not free).
  std::vector<std::vector<int>> place_triangles;
  std::vector<int> place_vertex;
  // Per triangle, the places that hold it; per vertex, whether a place of one point is there.
  std::vector<std::vector<int>> triangle_places;
  std::vector<char> point_place_at;
};

// `obstacles` convex and counter-clockwise; `obstacles_at(p)` the indices of those that may hold p (a
// superset). Checks `deadline` as it inserts.
FreeMesh triangulate_free_space(const std::vector<Polygon>& obstacles,
                                const std::function<const std::vector<int>&(const Vec2&)>& obstacles_at, const Rect& bounds,
                                const std::vector<Polygon>& places, const base::Deadline& deadline);

}  // namespace physltl::geometry
