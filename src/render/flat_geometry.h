#pragma once
// Coloured triangles collected on the CPU for one draw call (x y z r g b a per vertex, z = 0: on the floor,
// or in pixel space): floor paint, lines as thin quads (core OpenGL has no wide lines), polygons, panels.

#include "physltl/geometry/shapes.h"
#include "physltl/render/scene.h"

#include <vector>

namespace physltl::render {

class FlatGeometry {
 public:
  void triangle(const Vec2& a, const Vec2& b, const Vec2& c, const Color& color);
  void rectangle(const Vec2& min, const Vec2& max, const Color& color);
  void polygon(const geometry::Polygon& polygon, const Color& color);
  void line(const Vec2& from, const Vec2& to, double width, const Color& color);
  void outline(const geometry::Polygon& polygon, double width, const Color& color);
  // Consecutive points joined by lines with round joints, so sharp turns show no gaps.
  void polyline(const std::vector<Vec2>& points, double width, const Color& color);
  void disc(const Vec2& centre, double radius, const Color& color);

  const std::vector<float>& floats() const { return floats_; }

 private:
  void vertex(const Vec2& p, const Color& color);

  std::vector<float> floats_;
};

}  // namespace physltl::render
