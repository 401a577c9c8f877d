// The physics' overlap measure against an independent one: exact 2-D depths computed here from the
// replayed states (every body's outline where the state puts it), not from the engine's contacts. On
// shipped scenarios' plans both stay within max_overlap and agree (docs/physics.md, "How deep bodies
// overlap").

#include "test_problem.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace physltl::planning {
namespace {

using geometry::Polygon;

// How far the disc reaches into the convex polygon (negative: the gap between them).
double disc_depth(const Vec2& centre, double radius, const Polygon& convex) {
  double nearest = std::numeric_limits<double>::infinity();
  bool inside = true;
  const size_t n = convex.vertices.size();
  const double orientation = convex.signed_area() > 0 ? 1.0 : -1.0;
  for (size_t i = 0; i < n; ++i) {
    const Vec2& a = convex.vertices[i];
    const Vec2& b = convex.vertices[(i + 1) % n];
    const Vec2 edge = b - a;
    const double t = std::clamp((centre - a).dot(edge) / edge.squaredNorm(), 0.0, 1.0);
    nearest = std::min(nearest, (centre - (a + t * edge)).norm());
    inside = inside && orientation * geometry::cross(edge, centre - a) >= 0.0;
  }
  return inside ? radius + nearest : radius - nearest;
}

// The separating-axis depth of two convex polygons: the least overlap of their projections on an edge
// normal of either (negative: a gap along that normal).
double polygon_depth(const Polygon& p, const Polygon& q) {
  double least = std::numeric_limits<double>::infinity();
  for (const Polygon* edges : {&p, &q}) {
    const size_t n = edges->vertices.size();
    for (size_t i = 0; i < n; ++i) {
      const Vec2 edge = edges->vertices[(i + 1) % n] - edges->vertices[i];
      const Vec2 normal = Vec2(edge.y(), -edge.x()).normalized();
      const auto span = [&](const Polygon& poly) {
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        for (const Vec2& v : poly.vertices) lo = std::min(lo, v.dot(normal)), hi = std::max(hi, v.dot(normal));
        return std::pair(lo, hi);
      };
      const auto [p_lo, p_hi] = span(p);
      const auto [q_lo, q_hi] = span(q);
      least = std::min(least, std::min(p_hi, q_hi) - std::max(p_lo, q_lo));
    }
  }
  return least;
}

// The deepest overlap of the robot with a body and of a movable body with another, at any replayed state.
double deepest_overlap(const scenario::World& world, const Replay& replay) {
  std::vector<std::vector<Polygon>> fixed;
  for (const auto& body : world.fixed_bodies) {
    fixed.push_back(geometry::convex_parts_at(body.footprint.shape, body.footprint.pose, geometry::CircleAs::kInscribed));
  }
  double deepest = 0.0;
  for (size_t i = 0; i < replay.states.size(); ++i) {
    const scenario::EnvironmentState state = replay.states[i];
    std::vector<std::vector<Polygon>> movable;
    for (size_t b = 0; b < world.movable_bodies.size(); ++b) {
      movable.push_back(geometry::convex_parts_at(world.movable_bodies[b].footprint.shape, state.movable_poses[b],
                                                  geometry::CircleAs::kInscribed));
    }
    const auto deepest_with = [&](const std::vector<Polygon>& parts, const auto& depth_of) {
      for (const Polygon& part : parts) deepest = std::max(deepest, depth_of(part));
    };
    for (const auto* bodies : {&movable, &fixed}) {
      for (const auto& parts : *bodies) {
        deepest_with(parts, [&](const Polygon& part) { return disc_depth(state.robot_position, world.robot.radius, part); });
      }
    }
    for (size_t a = 0; a < movable.size(); ++a) {
      for (const auto* bodies : {&movable, &fixed}) {
        for (size_t b = bodies == &movable ? a + 1 : 0; b < bodies->size(); ++b) {
          for (const Polygon& part : movable[a]) {
            deepest_with((*bodies)[b], [&](const Polygon& other) { return polygon_depth(part, other); });
          }
        }
      }
    }
  }
  return deepest;
}

TEST(OverlapMeasure, AnIndependentExactMeasureOfShippedPlansAgreesWithThePhysicsWithinMaxOverlap) {
  for (const char* scenario : {"rooms.lua", "ordered.lua", "sorting.lua", "rooms_differential.lua"}) {
    const TestProblem p(scenario);
    const ValidatedPlan solution = solve_and_improve(p, 1, {});
    ASSERT_TRUE(solution.solved()) << scenario;
    const double independent = deepest_overlap(p.world, *solution.replay);
    const double engine = solution.replay->deepest_overlap_m();
    EXPECT_LE(independent, p.world.planner.max_overlap + 1e-3) << scenario;
    EXPECT_LE(engine, p.world.planner.max_overlap) << scenario;
    // ODE's box and prism depths are its own separating-axis depths, its contacts' at most 4 a pair.
    EXPECT_NEAR(independent, engine, 2e-3) << scenario;
  }
}

}  // namespace
}  // namespace physltl::planning
