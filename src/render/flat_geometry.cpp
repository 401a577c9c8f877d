#include "flat_geometry.h"

#include "triangulate.h"

#include <array>
#include <cmath>
#include <numbers>

namespace physltl::render {

void FlatGeometry::vertex(const Vec2& p, const Color& color) {
  floats_.insert(floats_.end(),
                 {static_cast<float>(p.x()), static_cast<float>(p.y()), 0.0f, color.r, color.g, color.b, color.a});
}

void FlatGeometry::triangle(const Vec2& a, const Vec2& b, const Vec2& c, const Color& color) {
  vertex(a, color);
  vertex(b, color);
  vertex(c, color);
}

void FlatGeometry::rectangle(const Vec2& min, const Vec2& max, const Color& color) {
  const Vec2 a = min, b(max.x(), min.y()), c = max, d(min.x(), max.y());
  triangle(a, b, c, color);
  triangle(a, c, d, color);
}

void FlatGeometry::polygon(const geometry::Polygon& polygon, const Color& color) {
  for (const auto& t : triangulate(polygon)) triangle(t[0], t[1], t[2], color);
}

void FlatGeometry::line(const Vec2& from, const Vec2& to, double width, const Color& color) {
  const Vec2 along = to - from;
  if (along.norm() == 0) return;
  const Vec2 side = Vec2(-along.y(), along.x()).normalized() * (width / 2);
  triangle(from - side, to - side, to + side, color);
  triangle(from - side, to + side, from + side, color);
}

void FlatGeometry::outline(const geometry::Polygon& polygon, double width, const Color& color) {
  const auto& v = polygon.vertices;
  for (std::size_t i = 0; i < v.size(); ++i) {
    line(v[i], v[(i + 1) % v.size()], width, color);
    disc(v[i], width / 2, color);
  }
}

void FlatGeometry::polyline(const std::vector<Vec2>& points, double width, const Color& color) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i + 1 < points.size()) line(points[i], points[i + 1], width, color);
    disc(points[i], width / 2, color);
  }
}

void FlatGeometry::disc(const Vec2& centre, double radius, const Color& color) {
  constexpr int kSides = 12;
  // The polygon's corners on the unit circle, computed once: a path has a disc at every physics step.
  static const std::array<Vec2, kSides + 1> corners = [] {
    std::array<Vec2, kSides + 1> c;
    for (int i = 0; i <= kSides; ++i) {
      const double a = 2 * std::numbers::pi * i / kSides;
      c[static_cast<std::size_t>(i)] = Vec2(std::cos(a), std::sin(a));
    }
    return c;
  }();
  for (int i = 0; i < kSides; ++i) {
    triangle(centre, centre + radius * corners[static_cast<std::size_t>(i)],
             centre + radius * corners[static_cast<std::size_t>(i) + 1], color);
  }
}

}  // namespace physltl::render
