#include "decomposition.h"

#include "physltl/geometry/free_space.h"
#include "ompl_automaton.h"

#include <algorithm>

namespace physltl::planners::ompl {

using geometry::Vec2;

std::vector<std::vector<int>> step_neighbours(const decomposition::Decomposition& decomposition, double reach) {
  const auto& triangles = decomposition.triangles();
  std::vector<geometry::Polygon> shapes;
  std::vector<geometry::Rect> bounds;
  for (const auto& t : triangles) {
    shapes.push_back(geometry::Polygon{{t.corners.begin(), t.corners.end()}});
    bounds.push_back(shapes.back().bounds());
  }
  std::vector<std::vector<int>> neighbours(triangles.size());
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    neighbours[i] = triangles[i].neighbors;
    for (std::size_t j = 0; j < triangles.size(); ++j) {
      const auto& a = bounds[i];
      const auto& b = bounds[j];
      if (i == j || b.min.x() > a.max.x() + reach || b.max.x() < a.min.x() - reach || b.min.y() > a.max.y() + reach ||
          b.max.y() < a.min.y() - reach) {
        continue;
      }
      scenario::Vec2 p, q;
      if (geometry::distance(shapes[i], shapes[j], p, q) <= reach &&
          std::find(neighbours[i].begin(), neighbours[i].end(), static_cast<int>(j)) == neighbours[i].end()) {
        neighbours[i].push_back(static_cast<int>(j));
      }
    }
  }
  return neighbours;
}

namespace {

ob::RealVectorBounds bounds_of(const scenario::World& world) {
  ob::RealVectorBounds b(2);
  b.setLow(0, world.workspace.bounds.min.x()), b.setHigh(0, world.workspace.bounds.max.x());
  b.setLow(1, world.workspace.bounds.min.y()), b.setHigh(1, world.workspace.bounds.max.y());
  return b;
}

}  // namespace

Triangles::Triangles(const decomposition::Decomposition& decomposition, const scenario::World& world,
                     const std::vector<std::vector<int>>& neighbours)
    : oc::Decomposition(2, bounds_of(world)), decomposition_(decomposition), neighbours_(neighbours) {}

int Triangles::locateRegion(const ob::State* state) const {
  const double* v = state->as<PhysicsSpace::StateType>()->values;
  return decomposition_.locate({v[0], v[1]});
}

void Triangles::project(const ob::State* state, std::vector<double>& coordinates) const {
  const double* v = state->as<PhysicsSpace::StateType>()->values;
  coordinates = {v[0], v[1]};
}

void Triangles::getNeighbors(int region, std::vector<int>& neighbours) const {
  const auto& n = neighbours_[static_cast<std::size_t>(region)];
  neighbours.insert(neighbours.end(), n.begin(), n.end());
}

void Triangles::sampleFromRegion(int region, ::ompl::RNG& rng, std::vector<double>& coordinates) const {
  const double u = rng.uniform01(), v = rng.uniform01();
  const Vec2 p = triangle(region).point_at(u, v);
  coordinates = {p.x(), p.y()};
}

void Triangles::sampleFullState(const ob::StateSamplerPtr& sampler, const std::vector<double>& coordinates,
                                ob::State* state) const {
  sampler->sampleUniform(state);
  double* v = state->as<PhysicsSpace::StateType>()->values;
  v[0] = coordinates[0], v[1] = coordinates[1];
}

oc::World RegionLabels::worldAtRegion(int triangle) {
  return region_letter(regions_, decomposition_.triangles()[static_cast<std::size_t>(triangle)].region);
}

}  // namespace physltl::planners::ompl
