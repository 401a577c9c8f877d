#include "physltl/geometry/convex_hull.h"

#include <algorithm>
#include <vector>

namespace physltl::geometry {

// Andrew's monotone chain: sort, then build the lower and the upper chain, each keeping left turns only.
Polygon convex_hull(std::span<const Vec2> points) {
  std::vector<Vec2> sorted(points.begin(), points.end());
  const auto lower_left = [](const Vec2& a, const Vec2& b) { return a.y() < b.y() || (a.y() == b.y() && a.x() < b.x()); };
  std::sort(sorted.begin(), sorted.end(), lower_left);
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  if (sorted.size() < 3) return Polygon{sorted};

  const auto turns_left = [](const Vec2& o, const Vec2& a, const Vec2& b) {
    const Vec2 u = a - o, v = b - o;
    return u.x() * v.y() - u.y() * v.x() > 0;
  };
  std::vector<Vec2> hull;
  hull.reserve(2 * sorted.size());
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t chain_start = hull.size();
    for (const Vec2& p : sorted) {
      while (hull.size() >= chain_start + 2 && !turns_left(hull[hull.size() - 2], hull.back(), p)) hull.pop_back();
      hull.push_back(p);
    }
    hull.pop_back();  // the chain's last point starts the other chain
    std::reverse(sorted.begin(), sorted.end());
  }
  return Polygon{hull};
}

}  // namespace physltl::geometry
