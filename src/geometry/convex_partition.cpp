#include "physltl/geometry/convex_partition.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Partition_traits_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_vertical_decomposition_2.h>
#include <CGAL/partition_2.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <list>

namespace physltl::geometry {
namespace {

using Inexact = CGAL::Exact_predicates_inexact_constructions_kernel;
using Exact = CGAL::Exact_predicates_exact_constructions_kernel;

Polygon counter_clockwise(Polygon p) {
  if (p.signed_area() < 0) std::reverse(p.vertices.begin(), p.vertices.end());
  return p;
}

// Corners where the outline goes straight on are no corners: a union of triangles has many.
template <class Points>
Polygon without_straight_corners(const Points& points) {
  Polygon p;
  for (const auto& q : points) p.vertices.emplace_back(CGAL::to_double(q.x()), CGAL::to_double(q.y()));
  bool removed = true;
  while (removed && p.vertices.size() > 3) {
    removed = false;
    const size_t n = p.vertices.size();
    for (size_t i = 0; i < n; ++i) {
      const Vec2& a = p.vertices[(i + n - 1) % n];
      const Vec2& b = p.vertices[i];
      const Vec2& c = p.vertices[(i + 1) % n];
      const double scale = std::max((b - a).norm() * (c - b).norm(), 1e-300);
      if (std::abs(cross(b - a, c - b)) <= 1e-12 * scale && (b - a).dot(c - b) > 0) {
        p.vertices.erase(p.vertices.begin() + static_cast<std::ptrdiff_t>(i));
        removed = true;
        break;
      }
    }
  }
  return p;
}

}  // namespace

bool is_convex(const Polygon& polygon) {
  const auto& v = polygon.vertices;
  const size_t n = v.size();
  if (n < 3) return false;
  int sign = 0;
  for (size_t i = 0; i < n; ++i) {
    const double turn = cross(v[(i + 1) % n] - v[i], v[(i + 2) % n] - v[(i + 1) % n]);
    const double scale = (v[(i + 1) % n] - v[i]).norm() * (v[(i + 2) % n] - v[(i + 1) % n]).norm();
    if (std::abs(turn) <= 1e-12 * std::max(scale, 1e-300)) continue;
    const int s = turn > 0 ? 1 : -1;
    if (sign != 0 && s != sign) return false;
    sign = s;
  }
  return sign != 0;
}

std::vector<Polygon> convex_partition(const Polygon& polygon) {
  const Polygon ccw = counter_clockwise(polygon);
  if (is_convex(ccw)) return {ccw};
  using Traits = CGAL::Partition_traits_2<Inexact>;
  Traits::Polygon_2 input;
  for (const Vec2& v : ccw.vertices) input.push_back(Traits::Point_2(v.x(), v.y()));
  std::list<Traits::Polygon_2> pieces;
  CGAL::approx_convex_partition_2(input.vertices_begin(), input.vertices_end(), std::back_inserter(pieces));
  std::vector<Polygon> out;
  for (const auto& piece : pieces) {
    Polygon p;
    for (auto it = piece.vertices_begin(); it != piece.vertices_end(); ++it) p.vertices.emplace_back(it->x(), it->y());
    out.push_back(counter_clockwise(std::move(p)));
  }
  return out;
}

namespace {

using ExactPolygon = CGAL::Polygon_2<Exact>;
using WithHoles = CGAL::Polygon_with_holes_2<Exact>;

// The union of `polygons` (any orientation, overlapping or touching) as CGAL's regions with holes; a
// degenerate polygon adds nothing, or with `strict` makes it nothing at all.
std::optional<std::vector<WithHoles>> united(const std::vector<Polygon>& polygons, bool strict) {
  std::vector<ExactPolygon> inputs;
  for (const Polygon& polygon : polygons) {
    if (polygon.vertices.size() < 3 || std::abs(polygon.signed_area()) < 1e-12 || !polygon.is_simple()) {
      if (strict) return std::nullopt;
      continue;
    }
    ExactPolygon p;
    for (const Vec2& v : counter_clockwise(polygon).vertices) p.push_back(Exact::Point_2(v.x(), v.y()));
    inputs.push_back(std::move(p));
  }
  std::vector<WithHoles> regions;
  if (inputs.empty()) return regions;
  CGAL::Polygon_set_2<Exact> set;
  set.join(inputs.begin(), inputs.end());
  set.polygons_with_holes(std::back_inserter(regions));
  return regions;
}

}  // namespace

std::vector<Polygon> convex_partition_of_union(const std::vector<Polygon>& polygons) {
  CGAL::Polygon_vertical_decomposition_2<Exact> decompose;
  std::vector<Polygon> out;
  const std::vector<WithHoles> regions = *united(polygons, false);
  for (const WithHoles& region : regions) {
    std::list<ExactPolygon> pieces;
    decompose(region, std::back_inserter(pieces));
    for (const ExactPolygon& piece : pieces) {
      Polygon p = counter_clockwise(without_straight_corners(piece.container()));
      if (p.vertices.size() >= 3 && std::abs(p.signed_area()) > 1e-12) out.push_back(std::move(p));
    }
  }
  return out;
}

std::optional<Polygon> union_outline(const std::vector<Polygon>& polygons) {
  const std::optional<std::vector<WithHoles>> regions = united(polygons, true);
  if (!regions || regions->size() != 1 || regions->front().has_holes() || regions->front().is_unbounded()) return std::nullopt;
  Polygon outline = counter_clockwise(without_straight_corners(regions->front().outer_boundary().container()));
  if (!outline.is_simple()) return std::nullopt;  // pieces that meet at a corner only
  return outline;
}

}  // namespace physltl::geometry
