#pragma once
// Our triangulation as OMPL's decomposition, labelled by region, for OMPL's product graph.

#include "physics_space.h"

#include "physltl/decomposition/decomposition.h"

#include <ompl/control/planners/ltl/PropositionalDecomposition.h>

#include <vector>

namespace physltl::planners::ompl {

// OMPL's product graph connects a triangle to the triangles its decomposition names as
// neighbours, and a propagation step moves the product to the triangle the step ends in. A step that
// crosses a thin triangle (a sliver in a doorway is narrower than one step's 5 cm) would land in a product
// state the graph does not have: LTLPlanner gives it the weight 0/0 and never grows from it, and an
// accepting state there is no goal. So OMPL's decomposition names as neighbours every triangle one valid
// step can reach: within the robot's largest valid speed times the step size. A step that lands beyond
// them (only an invalid, faster one could) is refused, and counted. The automaton reads the region the
// step ends in, as our planner's does.
std::vector<std::vector<int>> step_neighbours(const decomposition::Decomposition& decomposition, double reach);

// Regions are triangles, located by the robot's position.
class Triangles : public oc::Decomposition {
 public:
  Triangles(const decomposition::Decomposition& decomposition, const scenario::World& world,
            const std::vector<std::vector<int>>& neighbours);
  int getNumRegions() const override { return decomposition_.size(); }
  double getRegionVolume(int region) override { return triangle(region).area; }
  int locateRegion(const ob::State* state) const override;
  void project(const ob::State* state, std::vector<double>& coordinates) const override;
  void getNeighbors(int region, std::vector<int>& neighbours) const override;
  void sampleFromRegion(int region, ::ompl::RNG& rng, std::vector<double>& coordinates) const override;
  void sampleFullState(const ob::StateSamplerPtr& sampler, const std::vector<double>& coordinates,
                       ob::State* state) const override;

 private:
  const decomposition::Triangle& triangle(int region) const {
    return decomposition_.triangles()[static_cast<std::size_t>(region)];
  }
  const decomposition::Decomposition& decomposition_;
  const std::vector<std::vector<int>>& neighbours_;
};

// Each triangle's label: "in region r" for a triangle of region r, "in no region" otherwise, exactly the
// letters the automaton's transitions are keyed by (to_ompl_automaton).
class RegionLabels : public oc::PropositionalDecomposition {
 public:
  RegionLabels(const oc::DecompositionPtr& triangles, const decomposition::Decomposition& decomposition, int regions)
      : oc::PropositionalDecomposition(triangles), decomposition_(decomposition), regions_(regions) {}
  oc::World worldAtRegion(int triangle) override;
  int getNumProps() const override { return regions_; }

 private:
  const decomposition::Decomposition& decomposition_;
  const int regions_;
};

}  // namespace physltl::planners::ompl
