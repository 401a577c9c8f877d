#pragma once
// The object lead: how the search moves a body to where the task needs it, when the next move of the
// task's stages is the body's (stage_graph.h). The body's way is a distance field for its centre
// (geometry::DiscField: a disc of the body's inscribed radius among the fixed bodies and the bodies too
// heavy to push), so every place knows how far the body still has to go and in which direction. The
// robot's part follows from a state: push along the active mRegion whose push helps most along that way;
// first walk to it, round the body, when the robot stands elsewhere; from afar, follow the decomposition's
// triangles towards the body. docs/planner.md says why.

#include "physltl/decomposition/decomposition.h"
#include "physltl/geometry/disc_field.h"
#include "physltl/knowledge/abstract_knowledge.h"
#include "physltl/knowledge/kappa.h"
#include "physltl/knowledge/labelling.h"
#include "physltl/planning/plan.h"
#include "physltl/planning/random.h"
#include "physltl/planning/stage_graph.h"

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace physltl::planners::knowledge {

class ObjectLead {
 public:
  // One body move with its way.
  struct Goal {
    int body = 0;  // World::movable_bodies index
    const geometry::DiscField* way = nullptr;
  };

  ObjectLead(const scenario::World& world, const physltl::knowledge::AbstractKnowledge& knowledge,
             const decomposition::Decomposition& decomposition);

  // The goal of `move` where `centre_of(body)` gives each body's centre, its way computed on first use:
  // for a group, of its bodies not yet where the move wants them, the one with the least way left. Not
  // thread-safe: the search calls it between batches.
  Goal goal(const physltl::knowledge::Labelling& labelling, const planning::BodyMove& move, const std::function<geometry::Vec2(int)>& centre_of);

  // Metres the body's centre at `centre` still has to travel; infinite when it cannot get there.
  static double remaining(const Goal& goal, const geometry::Vec2& centre);
  // How many bodies of `move`'s part are where the move wants them (a group's progress within its stage).
  int placed_bodies(const physltl::knowledge::Labelling& labelling, const planning::BodyMove& move, const std::function<geometry::Vec2(int)>& centre_of) const;

  // Where the robot heads, from far away, to get to the body at `body`: a point a few triangles along the
  // decomposition's shortest way; nothing when the robot is near enough to act (target() takes over). Not
  // thread-safe (it keeps the triangles' distances to recent bodies' places).
  std::optional<geometry::Vec2> approach(const geometry::Vec2& robot, const geometry::Vec2& body);

  // Where the robot heads from `state` to move the goal's body on: past the body along a push while it
  // stands in the mRegion of that push, else to that mRegion, round the body.
  geometry::Vec2 target(const Goal& goal, const scenario::EnvironmentState& state, const physltl::knowledge::Kappa& kappa,
              planning::Random& random) const;

 private:
  const std::vector<double>& distances_to_triangle(int triangle);
  // Whether a body of `part` with its centre at `centre` is where place `place` of it wants it.
  bool placed(const physltl::knowledge::Labelling::NamedPart& part, int place, const geometry::Vec2& centre) const;
  // The way of World body `body` to place `place` of `part` (out of all its region sets for place 0).
  const geometry::DiscField& way(const physltl::knowledge::Labelling::NamedPart& part, int body, int place);

  const scenario::World& world_;
  const physltl::knowledge::AbstractKnowledge& knowledge_;
  const decomposition::Decomposition& decomposition_;
  const physltl::knowledge::RegionMap regions_;  // which region a body's centre is in, as the labelling reads it
  std::map<std::pair<int, int>, std::unique_ptr<geometry::DiscField>> ways_;  // by (body, place)
  std::map<int, std::vector<double>> triangle_distances_;                       // by target triangle
};

}  // namespace physltl::planners::knowledge
