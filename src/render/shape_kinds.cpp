// The renderer's table of shape kinds (shape_kinds.h).

#include "shape_kinds.h"

#include <array>

namespace physltl::render {
namespace {

using geometry::Vec2;

TriangleMesh no_mesh(const geometry::Shape&, double) { return {}; }
std::optional<Vec2> no_cube(const geometry::Shape&) { return std::nullopt; }

// A box is the unit cube scaled; its shadow its rectangle.
constexpr ShapeKindDrawing kBox{
    [](const geometry::Shape& s) { return std::optional<Vec2>(2 * s.half_extents()); },
    no_mesh,
    [](const geometry::Shape& s, const geometry::Pose2& pose) { return std::vector<ShadowShape>{{pose, s.half_extents(), 0.0}}; },
};

// A cylinder's shadow is a disc.
constexpr ShapeKindDrawing kCylinder{
    no_cube,
    [](const geometry::Shape& s, double height) { return cylinder_mesh(s.radius(), height, 48); },
    [](const geometry::Shape& s, const geometry::Pose2& pose) { return std::vector<ShadowShape>{{pose, Vec2::Zero(), s.radius()}}; },
};

// The rectangle of a local outline's bounds, placed.
ShadowShape bounds_shadow(const geometry::Rect& local, const geometry::Pose2& pose) {
  return {{geometry::to_world(pose, 0.5 * (local.min + local.max)), pose.yaw}, 0.5 * local.size(), 0.0};
}

// A polygon's mesh is a prism per convex part; its shadow the rectangle of its bounds, or of each part's
// where it is concave (an L's shadow does not fill its notch).
constexpr ShapeKindDrawing kPolygon{
    no_cube,
    [](const geometry::Shape& s, double height) { return prism_mesh(s.parts(), height); },
    [](const geometry::Shape& s, const geometry::Pose2& pose) {
      if (s.parts().size() <= 1 || s.outline().vertices.empty()) return std::vector<ShadowShape>{bounds_shadow(geometry::bounds(s, {}), pose)};
      std::vector<ShadowShape> shadows;
      for (const geometry::Polygon& part : s.parts()) {
        geometry::Rect local{part.vertices.front(), part.vertices.front()};
        for (const Vec2& v : part.vertices) local.min = local.min.cwiseMin(v), local.max = local.max.cwiseMax(v);
        shadows.push_back(bounds_shadow(local, pose));
      }
      return shadows;
    },
};

// geometry::Shape::Kind order.
constexpr std::array<const ShapeKindDrawing*, 3> kKinds = {&kBox, &kCylinder, &kPolygon};

}  // namespace

const ShapeKindDrawing& kind_of(const geometry::Shape& shape) { return *kKinds[static_cast<std::size_t>(shape.kind())]; }

}  // namespace physltl::render
