#pragma once
// What each kind of shape is to the knowledge layer, one row per kind (geometry/shape_kinds.h has the
// geometry's): the mRegion of each of its faces, and how the robot meets it where it stands (INFERENCE and
// the reachability grid). A new kind of body is one more row here.

#include "obstacle.h"

#include "physltl/knowledge/abstract_knowledge.h"

#include <optional>
#include <vector>

namespace physltl::knowledge {

// The robot needs this much of a face's contact segment free to push: a gap that admits it at a single
// point only is a numerical accident, not a place to stand.
inline constexpr double kMinFreeStretch = 1e-3;  // m

struct ShapeKindKnowledge {
  // The mRegion in front of face `face` (scenario::face_count numbers them), `depth` deep; nothing for a
  // face the robot cannot touch, one inside a notch of the body narrower than the robot (a concave polygon).
  std::optional<MRegionTemplate> (*face_template)(const geometry::Shape& shape, int face, double depth, double robot_radius);
  double (*distance)(const Obstacle& obstacle, const geometry::Vec2& p);
  // Obstacle::closer_than: appends the non-empty intervals.
  void (*closer_than)(const Obstacle& obstacle, const geometry::Vec2& origin, const geometry::Vec2& direction, double radius,
                      std::vector<Interval>& out);
};

const ShapeKindKnowledge& kind_of(const geometry::Shape& shape);

}  // namespace physltl::knowledge
