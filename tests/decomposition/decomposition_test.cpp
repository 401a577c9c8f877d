#include "physltl/decomposition/decomposition.h"

#include "physltl/scenario/load.h"

#include <gtest/gtest.h>

#include <numeric>
#include <queue>

namespace physltl::decomposition {
namespace {

scenario::World rooms() { return scenario::load_scenario(std::string(PHYSLTL_SOURCE_DIR) + "/scenarios/rooms.lua"); }

double free_area(const scenario::World& w) {
  double area = w.workspace.bounds.size().prod();
  for (const auto& f : w.fixed_bodies) area -= f.footprint.shape.area();
  return area;
}

TEST(Decomposition, TrianglesCoverExactlyTheFreeWorkspace) {
  const auto w = rooms();
  const auto d = Decomposition::build(w);
  const double area = std::accumulate(d.triangles().begin(), d.triangles().end(), 0.0,
                                      [](double a, const Triangle& t) { return a + t.area; });
  EXPECT_NEAR(area, free_area(w), 1e-6);
  for (const auto& t : d.triangles()) {
    for (const auto& f : w.fixed_bodies) EXPECT_FALSE(geometry::contains(f.footprint.shape, f.footprint.pose, t.centroid)) << f.name;
  }
}

TEST(Decomposition, EachRegionIsCoveredExactlyByItsTriangles) {
  const auto w = rooms();
  const auto d = Decomposition::build(w);
  for (size_t r = 0; r < w.regions.size(); ++r) {
    double area = 0;
    for (const auto& t : d.triangles()) {
      if (t.region == static_cast<int>(r)) area += t.area;
    }
    EXPECT_NEAR(area, std::abs(w.regions[r].polygon.signed_area()), 1e-6) << w.regions[r].name;
  }
}

TEST(Decomposition, RoomThreeIsAnIslandAndTheHallReachesRoomOne) {
  const auto w = rooms();
  const auto d = Decomposition::build(w);
  // Flood the adjacency graph from the robot's start.
  std::vector<bool> seen(d.size(), false);
  std::queue<int> todo;
  todo.push(d.locate(w.robot.start));
  seen[todo.front()] = true;
  while (!todo.empty()) {
    for (int n : d.triangles()[todo.front()].neighbors) {
      if (!seen[n]) todo.push(n), seen[n] = true;
    }
    todo.pop();
  }
  auto reached = [&](const std::string& name) {
    for (int i = 0; i < d.size(); ++i) {
      const int r = d.triangles()[i].region;
      if (r >= 0 && w.regions[r].name == name && seen[i]) return true;
    }
    return false;
  };
  EXPECT_TRUE(reached("p1"));
  EXPECT_TRUE(reached("p2"));
  EXPECT_TRUE(reached("p4"));
  EXPECT_FALSE(reached("p3"));
}

TEST(Decomposition, LocateFindsTheTriangleHoldingAPoint) {
  const auto d = Decomposition::build(rooms());
  for (int i = 0; i < d.size(); i += 7) EXPECT_EQ(d.locate(d.triangles()[i].centroid), i);
}

// Grid Steiner points and subdivided constraints keep edges within a small factor of the bound.
TEST(Decomposition, MaxEdgeBoundsTheTriangleSize) {
  const auto w = rooms();
  DecompositionOptions options;
  options.max_edge = 0.5;
  const auto d = Decomposition::build(w, options);
  for (const auto& t : d.triangles()) {
    for (int i = 0; i < 3; ++i) EXPECT_LE((t.corners[i] - t.corners[(i + 1) % 3]).norm(), 2 * 0.5);
  }
}

}  // namespace
}  // namespace physltl::decomposition
