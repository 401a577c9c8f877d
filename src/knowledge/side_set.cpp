#include "physltl/knowledge/side_set.h"

#include <cmath>

namespace physltl::knowledge {

geometry::Vec2 outward_normal(Side side) {
  switch (side) {
    case Side::kMinusX: return {-1.0, 0.0};
    case Side::kPlusX: return {1.0, 0.0};
    case Side::kMinusY: return {0.0, -1.0};
    case Side::kPlusY: return {0.0, 1.0};
  }
  return {0.0, 0.0};
}

geometry::Vec2 push_direction(Side side, const geometry::Pose2& body_pose) {
  const geometry::Vec2 n = -outward_normal(side);
  const double c = std::cos(body_pose.yaw), s = std::sin(body_pose.yaw);
  return {c * n.x() - s * n.y(), s * n.x() + c * n.y()};
}

}  // namespace physltl::knowledge
