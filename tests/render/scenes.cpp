#include "scenes.h"

#include <cstdint>
#include <limits>

namespace physltl::render::test {
namespace {

using geometry::Rect;

// Numerical Recipes' LCG: the same sequence on every platform, unlike std::uniform_real_distribution.
class Sequence {
 public:
  double next(double low, double high) {
    state_ = state_ * 1664525u + 1013904223u;
    return low + (high - low) * (state_ >> 8) / double(1u << 24);
  }

 private:
  std::uint32_t state_ = 12345;
};

}  // namespace

Overlay mregions_around_boxes(const scenario::World& world, double depth, int active_per_box) {
  Overlay overlay;
  for (std::size_t b = 0; b < world.movable_bodies.size(); ++b) {
    const scenario::MovableBody& body = world.movable_bodies[b];
    const Vec2 c = body.footprint.pose.position, h = body.footprint.shape.half_extents();
    const Rect sides[4] = {{{c.x() - h.x() - depth, c.y() - h.y()}, {c.x() - h.x(), c.y() + h.y()}},
                           {{c.x() + h.x(), c.y() - h.y()}, {c.x() + h.x() + depth, c.y() + h.y()}},
                           {{c.x() - h.x(), c.y() - h.y() - depth}, {c.x() + h.x(), c.y() - h.y()}},
                           {{c.x() - h.x(), c.y() + h.y()}, {c.x() + h.x(), c.y() + h.y() + depth}}};
    for (int i = 0; i < 4; ++i) {
      overlay.mregions.push_back({geometry::Polygon::from_rect(sides[i]), i < active_per_box, static_cast<int>(b)});
    }
  }
  return overlay;
}

Overlay synthetic_tree_of_rooms() {
  const Rect hall{{-5.5, -0.75}, {5.5, 0.75}}, doorway{{2.75, 0.75}, {3.25, 1.45}}, room{{0.35, 1.45}, {5.55, 4.55}};
  auto free = [&](const Vec2& p) { return hall.contains(p) || doorway.contains(p) || room.contains(p); };
  const Color hall_colour{0.35f, 0.45f, 0.75f}, room_colour{0.65f, 0.30f, 0.70f};

  Overlay overlay;
  std::vector<Vec2> nodes{{0.0, 0.0}};
  Sequence random;
  while (nodes.size() < 400) {
    // One draw after the other: the order two calls in one argument list run in is the compiler's (GCC
    // takes the last first, Clang the first), and the golden was drawn y first.
    const double y = random.next(-1, 5);
    const double x = random.next(-6, 6);
    const Vec2 sample(x, y);
    std::size_t nearest = 0;
    double best = std::numeric_limits<double>::max();
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      if ((nodes[i] - sample).norm() < best) best = (nodes[i] - sample).norm(), nearest = i;
    }
    const Vec2 step = nodes[nearest] + (sample - nodes[nearest]).normalized() * std::min(best, 0.35);
    if (!free(step)) continue;
    overlay.segments.push_back({nodes[nearest], step, room.contains(step) ? room_colour : hall_colour});
    nodes.push_back(step);
  }
  overlay.path = {{0.0, 0.0}, {2.2, 0.3}, {3.0, 0.7}, {3.0, 2.0}, {4.0, 3.2}, {4.8, 3.8}};
  for (double x = -6; x < 6; x += 2) {
    for (double y = -5; y < 5; y += 2) {
      overlay.decomposition.push_back({Vec2(x, y), Vec2(x + 2, y), Vec2(x + 2, y + 2)});
      overlay.decomposition.push_back({Vec2(x, y), Vec2(x + 2, y + 2), Vec2(x, y + 2)});
    }
  }
  overlay.legend = {"search tree: 400 nodes", "path to p2"};
  return overlay;
}

}  // namespace physltl::render::test
