#pragma once
// The paper's F(K, Pi) -> M_p: propositions whose regions the robot can never reach. Reachability is a
// flood fill over a grid in the robot's configuration space (workspace minus fixed bodies and bodies too
// heavy to push, each grown by the robot's radius). Movable bodies never block: the robot pushes them.

#include "physltl/base/deadline.h"
#include "physltl/knowledge/abstract_knowledge.h"

#include <span>
#include <string>
#include <vector>

namespace physltl::knowledge {

enum class Unreachability {
  kEnclosed,                  // not even a point-sized robot gets there: walls close the region off
  kGapNarrowerThanRobot,      // a point gets there, the robot does not: every way in is too narrow
  kNoRoomForRobot,            // the robot's centre fits nowhere inside the region
  kBlockedByUnpushableBodies, // reachable if the bodies too heavy to push were gone
  kBodyCannotMove,            // BODY@REGION: the body is too heavy to push and stands elsewhere
  kBodyCannotGetThere,        // BODY@REGION: no way in for the body's centre among what cannot move
};

// An object proposition a task names, BODY@REGION: the centre of a movable body in a region; or, for
// groups (scenario::Group), the centre of every body of the group in some region of the set.
struct ObjectProposition {
  std::string name;          // "crate@dock", "boxes@goals"
  std::vector<int> bodies;   // AbstractKnowledge::movable_bodies indices
  std::vector<int> regions;  // AbstractKnowledge::propositions indices
};

// What the knowledge layer concludes about one, before any planning. Sound only: a proposition is
// called unreachable or always true only when no plan could make it otherwise.
struct ObjectVerdict {
  std::string name, body, region;  // the atom, its body part and its region part as written
  std::vector<int> bodies, regions;  // as ObjectProposition
  bool reachable = true;     // the body's centre can be in the region at some time
  bool always_true = false;  // it is there and can never leave: the body cannot move
  std::string reason;        // why unreachable or always true; empty otherwise
};

struct InvalidProposition {
  std::string name;
  Unreachability why = Unreachability::kEnclosed;
  std::string reason;  // "p3: region enclosed by fixed walls"
};

struct Feasibility {
  double cell_size = 0.0;  // m, of the configuration-space grid
  // In AbstractKnowledge::propositions order, then the unreachable object propositions.
  std::vector<InvalidProposition> invalid;
  std::vector<ObjectVerdict> objects;  // one per object proposition asked about, in that order

  std::vector<std::string> invalid_names() const;
  std::vector<std::string> always_true_names() const;  // object propositions that always hold
  const InvalidProposition* find(const std::string& proposition) const;  // nullptr when valid
};

// Grid cell edge: a tenth of the robot's radius, kept within 2-5 cm; coarser only if the workspace would
// need more than kMaxGridCells cells.
inline constexpr long kMaxGridCells = 4'000'000;
double grid_cell_size(const AbstractKnowledge& knowledge);

// `objects`: the task's object propositions. A body that cannot move (too heavy to push) makes its
// propositions always true where it stands and unreachable elsewhere; a region its centre cannot get into,
// a disc of its inscribed radius among the fixed bodies, the bodies too heavy to push and the workspace's
// edge (geometry::DiscField), makes its proposition unreachable. A proposition about a group holds only
// when each of its bodies is in one of its regions: one body that can be in none makes it unreachable.
// The fields are large (up to a million cells each): once `deadline` comes, the object propositions not yet
// judged are left reachable (nothing is concluded without its field), and the run that gave the deadline
// ends at its next check.
Feasibility evaluate_feasibility(const AbstractKnowledge& knowledge, std::span<const ObjectProposition> objects = {},
                                 const base::Deadline& deadline = {});

}  // namespace physltl::knowledge
