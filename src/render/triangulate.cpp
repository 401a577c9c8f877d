#include "triangulate.h"

#include <algorithm>
#include <numeric>

namespace physltl::render {
namespace {

using geometry::Vec2;

double cross(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

bool inside_triangle(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c) {
  return cross(a, b, p) >= 0 && cross(b, c, p) >= 0 && cross(c, a, p) >= 0;
}

}  // namespace

std::vector<std::array<Vec2, 3>> triangulate(const geometry::Polygon& polygon) {
  std::vector<Vec2> v = polygon.vertices;
  if (polygon.signed_area() < 0) std::reverse(v.begin(), v.end());  // work counter-clockwise
  std::vector<std::size_t> remaining(v.size());
  std::iota(remaining.begin(), remaining.end(), 0);
  std::vector<std::array<Vec2, 3>> triangles;
  while (remaining.size() > 3) {
    const std::size_t n = remaining.size();
    bool clipped = false;
    for (std::size_t i = 0; i < n && !clipped; ++i) {
      const std::size_t ia = remaining[(i + n - 1) % n], ib = remaining[i], ic = remaining[(i + 1) % n];
      if (cross(v[ia], v[ib], v[ic]) <= 0) continue;  // reflex or degenerate corner: not an ear
      const bool empty = std::none_of(remaining.begin(), remaining.end(), [&](std::size_t j) {
        return j != ia && j != ib && j != ic && inside_triangle(v[j], v[ia], v[ib], v[ic]);
      });
      if (!empty) continue;
      triangles.push_back({v[ia], v[ib], v[ic]});
      remaining.erase(remaining.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
    }
    // Only a degenerate (e.g. collinear) remainder has no ear; it has no area to draw either.
    if (!clipped) return triangles;
  }
  if (remaining.size() == 3) triangles.push_back({v[remaining[0]], v[remaining[1]], v[remaining[2]]});
  return triangles;
}

}  // namespace physltl::render
