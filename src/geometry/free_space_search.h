#pragma once
// Exact shortest paths over the free space's triangles without a graph of corners: Polyanya's expansion
// (Cui, Harabor and Grastien, "Compromise-free pathfinding on a navigation mesh", IJCAI 2017) run as a
// continuous Dijkstra from a whole place. A search node is a cone of straight lines: from a root (a point
// the path has reached, or, leaving a place's edge, the parallel lines square to it) through an interval
// of one triangle's edge into the next triangle. It is projected across that triangle onto the other two
// edges; where the interval ends at a corner the path may turn round, the part behind it gets that corner
// as its root. Nodes come out nearest first, so a place is reached at its shortest distance the first time
// a node enters it. The cost follows the area the search sweeps, not the pairs of corners that see each
// other (a straight aisle between rows of boxes is one cone, where a visibility graph joins every pair of
// its corners).

#include "free_space_mesh.h"

#include <vector>

namespace physltl::geometry {

// The length of a shortest path from any point of place `source`'s free part to any point of each place's
// (infinity where there is none).
std::vector<double> distances_from_place(const FreeMesh& mesh, int source, const base::Deadline& deadline);

}  // namespace physltl::geometry
