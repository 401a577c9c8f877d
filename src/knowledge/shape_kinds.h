#pragma once
// What each kind of shape is to the knowledge layer, one row per kind (geometry/shape_kinds.h has the
// geometry's): the mRegion of each of its faces, and how the robot meets it where it stands (INFERENCE and
// the reachability grid). A new kind of body is one more row here.

#include "obstacle.h"

#include "physltl/knowledge/abstract_knowledge.h"

#include <vector>

namespace physltl::knowledge {

struct ShapeKindKnowledge {
  // The mRegion in front of face `face` (scenario::face_count numbers them), `depth` deep.
  MRegionTemplate (*face_template)(const geometry::Shape& shape, int face, double depth, double robot_radius);
  double (*distance)(const Obstacle& obstacle, const geometry::Vec2& p);
  // Obstacle::closer_than: appends the non-empty intervals.
  void (*closer_than)(const Obstacle& obstacle, const geometry::Vec2& origin, const geometry::Vec2& direction, double radius,
                      std::vector<Interval>& out);
};

const ShapeKindKnowledge& kind_of(const geometry::Shape& shape);

}  // namespace physltl::knowledge
