#pragma once
// Instantiated knowledge kappa and the paper's INFERENCE: which mRegions of each movable body are usable
// in a given environment state, and so the body's current type. A pure function of (K, E).

#include "physltl/geometry/point_grid.h"
#include "physltl/knowledge/abstract_knowledge.h"
#include "physltl/knowledge/face_set.h"
#include "physltl/scenario/state.h"

#include <span>
#include <vector>

namespace physltl::knowledge {

// free: pushable from every face; constraint-oriented: from some faces only; immovable: from none (or too
// heavy to push at all).
enum class BodyType { kFree, kConstraintOriented, kImmovable };
const char* type_name(BodyType type);  // "free", "constraint-oriented", "immovable"

struct BodyKappa {
  BodyType type = BodyType::kFree;
  FaceSet active_faces;  // faces whose mRegion the robot can stand in right now
  bool operator==(const BodyKappa&) const = default;
};

struct Kappa {
  std::vector<BodyKappa> bodies;  // World::movable_bodies order
  bool operator==(const Kappa&) const = default;
};

// The movable bodies' poses a kappa was inferred for, their positions on a grid: INFERENCE looks up the
// bodies near a contact segment, or near a body that moved, among the bodies near it.
class BodyLocator {
 public:
  BodyLocator() = default;
  // `cell`: the grid's cell side; by default about the size of INFERENCE's lookups. One cell as large as
  // the workspace makes every lookup a scan of all bodies (what tests compare the grid against).
  BodyLocator(const AbstractKnowledge& knowledge, std::span<const geometry::Pose2> poses, double cell = 0.0);

  std::span<const geometry::Pose2> poses() const { return poses_; }
  void move(std::size_t body, const geometry::Pose2& pose);
  // Replaces `out` with the bodies whose centres lie within `radius` of `p` in x and in y, in no order.
  void near(const geometry::Vec2& p, double radius, std::vector<int>& out) const { grid_.near(p, radius, out); }

 private:
  std::vector<geometry::Pose2> poses_;
  geometry::PointGrid grid_;
};

// kappa for state `state`. An mRegion is inactive while the robot, touching that side with its centre
// anywhere along it, would overlap a fixed body, another movable body or leave the workspace.
Kappa infer(const AbstractKnowledge& knowledge, const scenario::EnvironmentState& state);

// INFERENCE: E x kappa -> kappa'. Rewrites `kappa` in place for `state`, reusing its storage. The result
// equals infer(knowledge, state). `bodies`, when given, must hold `state`'s poses.
void infer(const AbstractKnowledge& knowledge, const scenario::EnvironmentState& state, Kappa& kappa);
void infer(const AbstractKnowledge& knowledge, const scenario::EnvironmentState& state, const BodyLocator& bodies,
           Kappa& kappa);

// INFERENCE after a change of state: `kappa` was inferred for the poses in `inferred_for`; this infers
// again only the bodies that moved and those a moved body came near, and moves `inferred_for` to
// `state`'s poses, so that a step that moves one box costs about one body's inference however many
// bodies the World has (plus a comparison of every pose). The result equals infer(knowledge, state).
void reinfer(const AbstractKnowledge& knowledge, const scenario::EnvironmentState& state, BodyLocator& inferred_for,
             Kappa& kappa);
// The same when only the bodies `maybe_moved` (indices) can differ from `inferred_for`: the others are
// not compared, so a step costs what its moving bodies cost.
void reinfer(const AbstractKnowledge& knowledge, const scenario::EnvironmentState& state, BodyLocator& inferred_for,
             Kappa& kappa, std::span<const int> maybe_moved);

// The world-frame direction a body at `pose` moves in when pushed from `mregion`'s face.
geometry::Vec2 push_direction(const MRegionTemplate& mregion, const geometry::Pose2& body_pose);

// The world-frame directions a body at `pose` can be pushed in now, one per active face.
std::vector<geometry::Vec2> allowed_push_directions(const MovableBodyKnowledge& body, const BodyKappa& kappa,
                                                    const geometry::Pose2& pose);

// mRegion strip of a template placed at a body pose, in the world frame.
geometry::OrientedBox mregion_at(const MRegionTemplate& mregion, const geometry::Pose2& body_pose);

}  // namespace physltl::knowledge
