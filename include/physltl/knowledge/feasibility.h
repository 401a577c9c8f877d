#pragma once
// The paper's F(K, Pi) -> M_p: propositions whose regions the robot can never reach. Reachability is a
// flood fill over a grid in the robot's configuration space (workspace minus fixed bodies and bodies too
// heavy to push, each grown by the robot's radius). Movable bodies never block: the robot pushes them.

#include "physltl/knowledge/abstract_knowledge.h"

#include <string>
#include <vector>

namespace physltl::knowledge {

enum class Unreachability {
  kEnclosed,                  // not even a point-sized robot gets there: walls close the region off
  kGapNarrowerThanRobot,      // a point gets there, the robot does not: every way in is too narrow
  kNoRoomForRobot,            // the robot's centre fits nowhere inside the region
  kBlockedByUnpushableBodies, // reachable if the bodies too heavy to push were gone
};

struct InvalidProposition {
  std::string name;
  Unreachability why = Unreachability::kEnclosed;
  std::string reason;  // "p3: region enclosed by fixed walls"
};

struct Feasibility {
  double cell_size = 0.0;  // m, of the configuration-space grid
  std::vector<InvalidProposition> invalid;  // in AbstractKnowledge::propositions order

  std::vector<std::string> invalid_names() const;
  const InvalidProposition* find(const std::string& proposition) const;  // nullptr when valid
};

// Grid cell edge: a tenth of the robot's radius, kept within 2-5 cm; coarser only if the workspace would
// need more than kMaxGridCells cells.
inline constexpr long kMaxGridCells = 4'000'000;
double grid_cell_size(const AbstractKnowledge& knowledge);

Feasibility evaluate_feasibility(const AbstractKnowledge& knowledge);

}  // namespace physltl::knowledge
